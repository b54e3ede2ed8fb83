#include "sensor/sensor_model.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::sensor {

double psf_reach_cm(const OpticsModel& optics, const PsfReach& reach) {
  return reach.diffraction_lambda_f * optics.diffraction_wavelength_cm * optics.f_number +
         reach.jitter_sigmas * optics.jitter_mrad * 1e-3 * optics.focal_length_cm +
         reach.defocus_blur_diameters * optics.defocus_cm / optics.f_number;
}

const PointSourceModel& SensorModel::point_sources() const {
  PointSourceModelCache& cache = *point_source_cache;
  std::call_once(cache.built, [&] { cache.model = build_point_source_model(optics, grid, fidelity()); });
  return cache.model;
}

const DetectorPattern& SensorModel::detector_pattern() const {
  DetectorPatternCache& cache = *detector_pattern_cache;
  std::call_once(cache.built, [&] {
    cache.pattern = build_detector_pattern(parameters.detector, grid.pixels_x * grid.pixels_y);
  });
  return cache.pattern;
}

std::shared_ptr<const SensorModel> resolve_sensor(const universe::SensorParameters& p) {
  auto model = std::make_shared<SensorModel>();
  model->parameters = p;
  model->metrics = compute_static_metrics(p);  // validates
  model->optics = OpticsModel::from_parameters(p);
  const Fidelity& f = p.fidelity;
  model->spectral = radiometry::SpectralView::make(p.band_low_um, p.band_high_um, p.spectral_intervals,
                                                   f.band_integration, f.spectral_quadrature);
  geometry::SampleGrid& g = model->grid;
  g.pixels_x = p.horizontal_pixels;
  g.pixels_y = p.vertical_pixels;
  g.per_pixel = f.samples_per_pixel;
  g.pitch_x_cm = model->metrics.pixel_pitch_x_cm;
  g.pitch_y_cm = model->metrics.pixel_pitch_y_cm;
  g.focal_length_cm = p.focal_length_cm;
  // Guard band: the PSF's reach in whole pixels plus one, at least one pixel,
  // at most the sensor's size.
  const double pitch = std::min(g.pitch_x_cm, g.pitch_y_cm);
  const auto need = static_cast<std::int64_t>(std::ceil(psf_reach_cm(model->optics, f.scene_psf_reach) / pitch)) + 1;
  g.guard_pixels = std::clamp<std::int64_t>(need, 1, std::max<std::int64_t>(1, std::max(g.pixels_x, g.pixels_y)));
  return model;
}

}  // namespace eoir::sensor
