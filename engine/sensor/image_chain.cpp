#include "sensor/image_chain.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/constants.hpp"
#include "core/parallel_ranges.hpp"
#include "sensor/detector.hpp"
#include "sensor/scene_convolution.hpp"

namespace eoir::sensor {

std::vector<PointSourceSignal> point_source_signals(const SensorModel& model, const radiometry::RadianceImage& scene) {
  const geometry::SampleGrid& g = scene.grid;
  const StaticMetrics& m = model.metrics;
  std::vector<PointSourceSignal> signals;
  signals.reserve(scene.point_sources.size());
  for (const radiometry::PointSource& ps : scene.point_sources) {
    PointSourceSignal s;
    s.x_px = g.pixel_x_of(ps.column);
    s.y_px = g.pixel_y_of(ps.row);
    s.streak_x_px = ps.streak_columns / static_cast<double>(g.per_pixel);
    s.streak_y_px = ps.streak_rows / static_cast<double>(g.per_pixel);
    s.electrons = m.peak_irradiance_responsivity * ps.irradiance_W_cm2 / m.ensquared_energy;
    signals.push_back(s);
  }
  return signals;
}

SensorImage render_sensor_image(const SensorModel& model, const radiometry::RadianceImage& scene,
                                std::mt19937_64& rng, unsigned threads, SensorImage storage,
                                const SceneRowSource* scene_rows) {
  using clock = std::chrono::steady_clock;
  const auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  const auto t0 = clock::now();
  const universe::SensorParameters& p = model.parameters;
  const StaticMetrics& m = model.metrics;
  const geometry::SampleGrid& g = scene.grid;
  const std::int64_t nx = g.pixels_x, ny = g.pixels_y;
  SensorImage out;
  out.electrons = std::move(storage.electrons);
  // Extended sources: r_L = R_peak,L * (L conv PSF) averaged over the pixel (eq. 49).
  std::vector<double> mean =
      scene_rows ? pixel_radiance_in_strips(model, g, *scene_rows, threads, std::move(storage.mean_electrons))
                 : pixel_radiance(model, scene, threads, std::move(storage.mean_electrons));
  const auto t1 = clock::now();
  for (double& v : mean) v *= m.peak_radiance_responsivity;
  // Point sources: r_E = R_peak,E E^ps EOD / ENSQ (eqs. 50-51), EOD from the
  // sensor's point-source model (tables built once: no FFT here), streaks
  // spread along their segment.
  if (!scene.point_sources.empty())
    render_point_sources(model.point_sources(), point_source_signals(model, scene), nx, ny, mean);
  const auto t2 = clock::now();
  out.adu = std::move(storage.adu);
  if (p.detector.enabled) {
    // The detector stage in place of eqs. 53-55 (detector.hpp).
    apply_detector(p.detector, model.detector_pattern(), mean, p.integration_time_ms * 1e-3, p.noise_enabled, rng,
                   out.electrons, out.adu);
    out.mean_electrons = std::move(mean);
    out.convolution_s = seconds(t0, t1);
    out.point_sources_s = seconds(t1, t2);
    out.noise_s = seconds(t2, clock::now());
    return out;
  }
  out.adu.clear();
  // Noise (eqs. 53-54) and saturation (eq. 55); zero dark offset (5.11.3).
  out.electrons.resize(mean.size());
  std::normal_distribution<double> normal(0.0, 1.0);
  const double dark2 = m.dark_noise_electrons * m.dark_noise_electrons;
  for (std::size_t i = 0; i < mean.size(); ++i) {
    double r = mean[i];
    if (p.noise_enabled) r += std::sqrt(dark2 + std::max(mean[i], 0.0)) * normal(rng);
    out.electrons[i] = std::min(r, m.saturation_electrons);
  }
  out.mean_electrons = std::move(mean);
  out.convolution_s = seconds(t0, t1);
  out.point_sources_s = seconds(t1, t2);
  out.noise_s = seconds(t2, clock::now());
  return out;
}

}  // namespace eoir::sensor
