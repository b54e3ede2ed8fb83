// BRDF of spec 4.1.4.1 eq. 1: construction (the per-incidence normalization
// tables) and evaluation per surface sample and light source, against the
// forward-lobe sharpness alpha (beta = alpha / 4, k0 = 0.1, k1 = 0.5).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "radiometry/brdf.hpp"

namespace {

using eoir::radiometry::Brdf;
using eoir::radiometry::BrdfParameters;

BrdfParameters parameters_for(const benchmark::State& state) {
  const double alpha = static_cast<double>(state.range(0));
  return {0.1, 0.5, alpha, alpha / 4.0};
}

void BM_BrdfConstruct(benchmark::State& state) {
  const BrdfParameters parameters = parameters_for(state);
  for (auto _ : state) {
    Brdf brdf(parameters);
    benchmark::DoNotOptimize(&brdf);
  }
}

void BM_BrdfValue(benchmark::State& state) {
  const Brdf brdf(parameters_for(state));
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> directions;  // upper hemisphere, uniform in solid angle
  for (int i = 0; i < 1024; ++i) {
    const double cos_polar = u(rng), azimuth = 2.0 * 3.14159265358979 * u(rng);
    const double sin_polar = std::sqrt(1.0 - cos_polar * cos_polar);
    directions.emplace_back(sin_polar * std::cos(azimuth), sin_polar * std::sin(azimuth), cos_polar);
  }
  const Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  std::size_t i = 0;
  for (auto _ : state) {
    const double value = brdf.value(directions[i & 1023u], directions[(i * 7 + 1) & 1023u], normal);
    benchmark::DoNotOptimize(value);
    ++i;
  }
}

}  // namespace

BENCHMARK(BM_BrdfConstruct)->Arg(0)->Arg(1)->Arg(20)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BrdfValue)->Arg(0)->Arg(1)->Arg(20)->Arg(100)->Arg(1000);
BENCHMARK_MAIN();
