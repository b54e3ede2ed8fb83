// The detector stage after eq. 55 (sensor/detector.hpp; issue 23 items 4
// and 7): its cost per pixel beside the spec's noise and saturation (eqs.
// 53-55), measured in one run on the same image.
//
// Sensor: spec 7.6 Table 3 (its pixel pitch) with N x N pixels, a uniform
// scene whose noise-free response is `level` electrons per pixel.
//
//  - BM_DetectorStage/N/level: each iteration renders the sensor image
//    (render_sensor_image) twice, with detector_model off (the spec's
//    Gaussian noise, eqs. 53-54, and saturation, eq. 55) and on (Poisson
//    photon and dark noise, PRNU, DSNU, hot and dead pixels, full well, read
//    noise, ADC), noise on in both. Counters from each stage's own time
//    (SensorImage::noise_s): spec_ns_per_pixel, detector_ns_per_pixel and
//    their ratio. The Poisson draw's cost grows from low counts (inversion)
//    to high (rejection), hence three levels.
//  - BM_DetectorPattern/N: the one-off build of the fixed pattern (once per
//    change of the sensor's properties), ns_per_pixel.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <random>

#include "sensor/detector.hpp"
#include "sensor/image_chain.hpp"
#include "sensor/sensor_model.hpp"

namespace {

using eoir::universe::SensorParameters;

SensorParameters square(std::int64_t pixels, bool detector) {
  SensorParameters p;  // Table 3: 128 pixels over 0.5 deg
  p.horizontal_pixels = p.vertical_pixels = pixels;
  p.horizontal_fov_deg = p.vertical_fov_deg = 0.5 * static_cast<double>(pixels) / 128.0;
  p.noise_enabled = true;
  p.detector.enabled = detector;
  p.detector.dark_current_e_s = 20.0;
  p.detector.dsnu_e_s = 2.0;
  p.detector.prnu_fraction = 0.01;
  p.detector.hot_pixel_fraction = 1e-4;
  p.detector.dead_pixel_fraction = 1e-4;
  p.detector.read_noise_e = 5.0;
  p.detector.gain_e_per_adu = 2.0;
  p.detector.full_well_e = 2.0e5;
  return p;
}

// A uniform scene on the model's grid whose response is `level_e` electrons.
eoir::radiometry::RadianceImage uniform(const eoir::sensor::SensorModel& model, double level_e) {
  eoir::radiometry::RadianceImage scene;
  scene.grid = model.grid;
  scene.radiance_W_cm2_sr.assign(static_cast<std::size_t>(model.grid.width() * model.grid.height()),
                                 level_e / model.metrics.peak_radiance_responsivity);
  return scene;
}

void BM_DetectorStage(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const auto level = static_cast<double>(state.range(1));
  const auto spec = eoir::sensor::resolve_sensor(square(n, false));
  const auto detector = eoir::sensor::resolve_sensor(square(n, true));
  detector->detector_pattern();  // the one-off build, outside the timing
  const auto scene = uniform(*spec, level);
  std::mt19937_64 rng(1);
  eoir::sensor::SensorImage a = eoir::sensor::render_sensor_image(*spec, scene, rng);
  eoir::sensor::SensorImage b = eoir::sensor::render_sensor_image(*detector, scene, rng);
  double spec_s = 0, detector_s = 0;
  int frames = 0;
  for (auto _ : state) {
    a = eoir::sensor::render_sensor_image(*spec, scene, rng, 0, std::move(a));
    b = eoir::sensor::render_sensor_image(*detector, scene, rng, 0, std::move(b));
    benchmark::DoNotOptimize(a.electrons.data());
    benchmark::DoNotOptimize(b.adu.data());
    spec_s += a.noise_s;
    detector_s += b.noise_s;
    ++frames;
  }
  const double pixels = static_cast<double>(n * n) * frames;
  state.counters["spec_ns_per_pixel"] = 1e9 * spec_s / pixels;
  state.counters["detector_ns_per_pixel"] = 1e9 * detector_s / pixels;
  state.counters["detector_over_spec"] = detector_s / spec_s;
}

void BM_DetectorPattern(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const SensorParameters p = square(n, true);
  for (auto _ : state) benchmark::DoNotOptimize(eoir::sensor::build_detector_pattern(p.detector, n * n));
  // time / (1e-9 n^2 iterations): nanoseconds per pixel.
  state.counters["ns_per_pixel"] = benchmark::Counter(
      1e-9 * static_cast<double>(n * n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(BM_DetectorStage)
    ->ArgsProduct({{256, 1024}, {10, 1000, 100000}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_DetectorPattern)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
