// Band integration (eq. 48) as a fidelity knob (DESIGN.md 4): the grid sum
// over N spectral intervals (midpoint and the spec 5.3 left-edge rule)
// against the exact Planck integral, for 150 K and 300 K blackbodies in
// 8-12 um. Time per band radiance and the relative error as counters; the
// frame-level cost of the same knob is BM_FrameSpectral in bench_frame.
#include <benchmark/benchmark.h>

#include <cmath>

#include "radiometry/band_integral.hpp"

namespace {

using eoir::radiometry::SpectralBand;
using eoir::radiometry::SpectralQuadrature;

void grid(benchmark::State& state, SpectralQuadrature rule) {
  const SpectralBand band{8.0, 12.0, state.range(0)};
  const double exact150 = eoir::radiometry::planck_band_radiance(150.0, 8.0, 12.0);
  const double exact300 = eoir::radiometry::planck_band_radiance(300.0, 8.0, 12.0);
  double l150 = 0, l300 = 0;
  for (auto _ : state) {
    l150 = eoir::radiometry::grid_planck_band_radiance(150.0, band, rule);
    l300 = eoir::radiometry::grid_planck_band_radiance(300.0, band, rule);
    benchmark::DoNotOptimize(&l150);
    benchmark::DoNotOptimize(&l300);
  }
  state.counters["rel_error_150K"] = std::abs(l150 / exact150 - 1.0);
  state.counters["rel_error_300K"] = std::abs(l300 / exact300 - 1.0);
  state.counters["intervals"] = static_cast<double>(band.intervals);
}

void BM_BandGridMidpoint(benchmark::State& state) { grid(state, SpectralQuadrature::interval_midpoint); }
void BM_BandGridLeftEdge(benchmark::State& state) { grid(state, SpectralQuadrature::interval_left_edge); }

void BM_BandExact(benchmark::State& state) {
  double l150 = 0, l300 = 0;
  for (auto _ : state) {
    l150 = eoir::radiometry::planck_band_radiance(150.0, 8.0, 12.0);
    l300 = eoir::radiometry::planck_band_radiance(300.0, 8.0, 12.0);
    benchmark::DoNotOptimize(&l150);
    benchmark::DoNotOptimize(&l300);
  }
  state.counters["rel_error_150K"] = 0.0;
  state.counters["rel_error_300K"] = 0.0;
}

}  // namespace

BENCHMARK(BM_BandGridMidpoint)->Arg(1)->Arg(2)->Arg(3)->Arg(5)->Arg(10)->Arg(20)->Arg(50)->Arg(100)->Arg(1000);
BENCHMARK(BM_BandGridLeftEdge)->Arg(1)->Arg(2)->Arg(3)->Arg(5)->Arg(10)->Arg(20)->Arg(50)->Arg(100)->Arg(1000);
BENCHMARK(BM_BandExact);
BENCHMARK_MAIN();
