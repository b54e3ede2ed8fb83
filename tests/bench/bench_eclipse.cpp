// Cost of the solar-disk visible fraction (geometry/eclipse.hpp, spec 4.1.5.3
// culling, 6.1.2 penumbra), called per surface patch and per point source:
// full sunlight (the early out), penumbra and umbra, against a sphere and
// the WGS84 spheroid, and a scene with N occulters (time per call; the
// counter ns_per_occulter divides by N).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "geometry/eclipse.hpp"

namespace {

using eoir::geometry::Occulter;
using eoir::geometry::Vec3;

constexpr double kAu = 149597870700.0, kSunRadius = 695700e3;
constexpr double kA = 6378137.0, kC = 6356752.314245, kGeo = 42164.2e3;
const Vec3 kSun = kAu * Vec3::UnitX();

Occulter earth(bool spheroid) {
  return spheroid ? Occulter{Vec3::Zero(), kA, kC, Vec3(0.01, 0.02, 1.0)} : Occulter::sphere(Vec3::Zero(), kA);
}

// 1024 points on a GEO arc centred on true anomaly nu0 (deg), half-width w (deg).
std::vector<Vec3> arc(double nu0_deg, double w_deg) {
  std::vector<Vec3> p;
  for (int i = 0; i < 1024; ++i) {
    const double nu = (nu0_deg + w_deg * (2.0 * i / 1023.0 - 1.0)) * M_PI / 180.0;
    p.emplace_back(kGeo * std::cos(nu), kGeo * std::sin(nu), 1e3 * (i % 7));
  }
  return p;
}

void run(benchmark::State& state, const std::vector<Vec3>& points, const std::vector<Occulter>& occ) {
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    sum += eoir::geometry::solar_disk_visible_fraction(points[i++ & 1023], kSun, kSunRadius, occ);
    benchmark::DoNotOptimize(sum);
  }
  state.counters["mean_fraction"] = sum / static_cast<double>(state.iterations());
  state.counters["ns_per_occulter"] =
      benchmark::Counter(static_cast<double>(state.iterations() * occ.size()) * 1e-9,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// arg 0: sphere, 1: spheroid.
void BM_EclipseSunlit(benchmark::State& state) { run(state, arc(90.0, 80.0), {earth(state.range(0) != 0)}); }
void BM_EclipsePenumbra(benchmark::State& state) {
  // The GEO sunset: Earth's limb across the Sun (spec 6.1.2), every point partial.
  run(state, arc(180.0 - 8.866, 0.25), {earth(state.range(0) != 0)});
}
void BM_EclipseUmbra(benchmark::State& state) { run(state, arc(180.0, 7.0), {earth(state.range(0) != 0)}); }

// N occulters (the Earth, the Moon and small spheres), none over the Sun.
void BM_EclipseSunlitScene(benchmark::State& state) {
  std::vector<Occulter> occ = {earth(true), Occulter::sphere(Vec3(-3.0e8, 2.4e8, 0.0), 1737.4e3)};
  for (int k = 2; k < state.range(0); ++k) {
    const double nu = 0.7 * k;
    occ.push_back(Occulter::sphere(Vec3(7.0e6 * std::cos(nu), 7.0e6 * std::sin(nu), 1e5 * k), 5.0));
  }
  run(state, arc(90.0, 80.0), occ);
}

}  // namespace

BENCHMARK(BM_EclipseSunlit)->Arg(0)->Arg(1);
BENCHMARK(BM_EclipsePenumbra)->Arg(0)->Arg(1);
BENCHMARK(BM_EclipseUmbra)->Arg(0)->Arg(1);
BENCHMARK(BM_EclipseSunlitScene)->Arg(2)->Arg(16)->Arg(26);
BENCHMARK_MAIN();
