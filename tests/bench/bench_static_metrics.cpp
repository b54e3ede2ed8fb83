// compute_static_metrics against the PSF FFT grid size (DESIGN.md section 4):
// time, and the ensquared-energy error against the 1024 result as a counter.
// DoNotOptimize takes the whole StaticMetrics: on a lone double, GCC may pick
// the "+r" alternative of its asm constraint and corrupt the value.
#include <benchmark/benchmark.h>

#include <cmath>

#include "sensor/static_metrics.hpp"

namespace {
using eoir::sensor::SensorParameters;

// Times compute_static_metrics for `p` at the benchmark's psf_grid_size and
// reports its ensquared energy and the error against psf_grid_size 1024.
void run(benchmark::State& state, SensorParameters p) {
  SensorParameters ref = p;
  ref.fidelity.psf_grid_size = 1024;
  const double reference = eoir::sensor::compute_static_metrics(ref).ensquared_energy;
  p.fidelity.psf_grid_size = state.range(0);
  double ensq = 0.0;
  for (auto _ : state) {
    eoir::sensor::StaticMetrics m = eoir::sensor::compute_static_metrics(p);
    benchmark::DoNotOptimize(m);
    ensq = m.ensquared_energy;
  }
  state.counters["ensq"] = ensq;
  state.counters["ensq_error_vs_1024"] = std::abs(ensq - reference);
}

// The spec 7.6 Table 3 sensor.
void BM_StaticMetrics(benchmark::State& state) { run(state, SensorParameters{}); }

// The same with aberration, defocus and jitter (every OTF factor evaluated).
void BM_StaticMetricsAberrated(benchmark::State& state) {
  SensorParameters p;
  p.image_quality = eoir::universe::ImageQuality::mild;
  p.defocus_mm = 0.1;
  p.jitter_mrad = 0.01;
  run(state, p);
}

// Pixels of 140 lambda F# (spec 7.8 kind of wide-field LWIR sensor, 24 deg
// over 128 pixels at f = 147 cm, 10 um, F/3.5): the folded-spectrum path.
void BM_StaticMetricsLargePixels(benchmark::State& state) {
  SensorParameters p;
  p.horizontal_fov_deg = p.vertical_fov_deg = 24.0;
  p.band_low_um = 8.0;
  p.band_high_um = 12.0;
  p.diffraction_wavelength_um = 10.0;
  run(state, p);
}

}  // namespace

BENCHMARK(BM_StaticMetrics)->Arg(128)->Arg(256)->Arg(512)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StaticMetricsAberrated)->Arg(128)->Arg(256)->Arg(512)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StaticMetricsLargePixels)->Arg(128)->Arg(512)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
