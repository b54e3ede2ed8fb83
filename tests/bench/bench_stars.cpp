// The star catalogue (issue 21 item 3): opening the mapped Hipparcos/Tycho-2
// file (no star is read), and a frame's star query for a 1-degree field
// (the cells the cone meets, stars to V = 10.5, each candidate made and
// culled on its position as scene/sky.cpp does) at high galactic latitude and
// in the Milky Way. Target: the query at or below 1 ms.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "universe/star_catalog.hpp"

namespace u = eoir::universe;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Eigen::Vector3d direction(double ra_deg, double dec_deg) {
  return {std::cos(dec_deg * kDeg) * std::cos(ra_deg * kDeg), std::cos(dec_deg * kDeg) * std::sin(ra_deg * kDeg),
          std::sin(dec_deg * kDeg)};
}

void BM_OpenCatalogue(benchmark::State& state) {
  for (auto _ : state) {
    const auto c = u::StarCatalog::load_binary(EOIR_STAR_CATALOGUE_PATH);
    benchmark::DoNotOptimize(c.size());
  }
}
BENCHMARK(BM_OpenCatalogue)->Unit(benchmark::kMicrosecond);

// A 1-degree field (half-diagonal 0.71 deg, plus the sky.cpp margins: 0.8 deg).
void query(benchmark::State& state, const Eigen::Vector3d& axis) {
  const auto c = u::StarCatalog::load_binary(EOIR_STAR_CATALOGUE_PATH);
  const double cone = 0.8 * kDeg, cos_cone = std::cos(cone);
  std::size_t stars = 0;
  for (auto _ : state) {
    stars = 0;
    for (const std::size_t i : c.select_in_cone(axis, cone, 10.5).indices) {
      if (c.unit_vector(i).dot(axis) < cos_cone) continue;
      benchmark::DoNotOptimize(c.star(i));
      ++stars;
    }
  }
  state.counters["stars"] = static_cast<double>(stars);
}

void BM_QueryOneDegreeHighLatitude(benchmark::State& state) { query(state, direction(192.9, 27.1)); }  // NGP
BENCHMARK(BM_QueryOneDegreeHighLatitude)->Unit(benchmark::kMicrosecond);

void BM_QueryOneDegreeGalacticCentre(benchmark::State& state) { query(state, direction(266.4, -28.9)); }
BENCHMARK(BM_QueryOneDegreeGalacticCentre)->Unit(benchmark::kMicrosecond);

void BM_QueryOneDegreeRandom(benchmark::State& state) {
  const auto c = u::StarCatalog::load_binary(EOIR_STAR_CATALOGUE_PATH);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0), angle(0.0, 360.0);
  for (auto _ : state) {
    const Eigen::Vector3d axis = direction(angle(rng), std::asin(uniform(rng)) / kDeg);
    for (const std::size_t i : c.select_in_cone(axis, 0.8 * kDeg, 10.5).indices)
      if (c.unit_vector(i).dot(axis) >= std::cos(0.8 * kDeg)) benchmark::DoNotOptimize(c.star(i));
  }
}
BENCHMARK(BM_QueryOneDegreeRandom)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
