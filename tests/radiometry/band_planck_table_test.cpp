// radiometry/band_planck_table.hpp: the tabulated band radiance against the
// term-by-term sum of eq. 48 (w_i B(lambda_i, T) over the grid), within
// 1e-12 relative at 20,000 temperatures from 30 to 1200 K (the interpolation
// error of cubic Hermite in 1/T at 1e-6 K^-1 node spacing is ~1e-13); equal
// to it off the table and where the band radiance underflows.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "radiometry/band_planck_table.hpp"
#include "radiometry/planck.hpp"

namespace {

using eoir::radiometry::BandPlanckTable;
using eoir::radiometry::SpectralBand;

std::vector<double> midpoints(const SpectralBand& b) {
  std::vector<double> w;
  for (std::int64_t i = 0; i < b.intervals; ++i) w.push_back(b.low_um + (static_cast<double>(i) + 0.5) * b.interval_um());
  return w;
}

TEST(BandPlanckTable, InterpolatesTheSumTo1e12) {
  const SpectralBand bands[] = {{0.45, 0.75, 10}, {3.0, 5.0, 10}, {8.0, 12.0, 10}, {0.3, 14.0, 100}, {8.0, 12.0, 1}};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> log_T(std::log(30.0), std::log(1200.0));
  for (const SpectralBand& b : bands) {
    std::vector<double> weights;  // a non-gray emissivity
    for (std::int64_t i = 0; i < b.intervals; ++i) weights.push_back(0.6 + 0.3 * std::sin(static_cast<double>(i)));
    const BandPlanckTable table(b, midpoints(b), weights);
    double worst = 0, worst_T = 0;
    for (int k = 0; k < 20000; ++k) {
      const double T = std::exp(log_T(rng));
      const double expected = table.direct(T);
      if (expected < 1e-290) continue;  // underflow: checked below
      const double e = std::abs(table.radiance(T) / expected - 1.0);
      if (e > worst) { worst = e; worst_T = T; }
    }
    EXPECT_LT(worst, 1e-12) << b.low_um << "-" << b.high_um << " um, at " << worst_T << " K";
    // The direct sum is eq. 48 on the grid: sum_i w_i B(lambda_i, T) dlambda.
    double sum = 0;
    for (std::int64_t i = 0; i < b.intervals; ++i)
      sum += weights[static_cast<std::size_t>(i)] * eoir::radiometry::planck_radiance(midpoints(b)[static_cast<std::size_t>(i)], 300.0);
    EXPECT_DOUBLE_EQ(table.direct(300.0), sum * b.interval_um());
  }
}

// blend (a land cover under the brightness map: (1 - s) B + s eps B with one
// exp): against the two direct sums within 1e-12 over the same bands and
// temperatures, for weights s in [0, 1]; within 1e-14 of the two look-ups
// (also at 12-20 K, where the visible band underflows); off the table and at
// NaN the two look-ups' sum.
TEST(BandPlanckTable, BlendOfTwoTablesIsTheirSumWithOneExp) {
  const SpectralBand bands[] = {{0.45, 0.75, 10}, {3.0, 5.0, 10}, {8.0, 12.0, 10}, {0.3, 14.0, 100}};
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> log_T(std::log(30.0), std::log(1200.0)), unit(0.0, 1.0);
  for (const SpectralBand& b : bands) {
    std::vector<double> eps;  // 1 - SRF of a land cover
    for (std::int64_t i = 0; i < b.intervals; ++i)
      eps.push_back(0.9 - 0.4 * std::abs(std::sin(0.7 * static_cast<double>(i))));
    const BandPlanckTable black(b, midpoints(b), std::vector<double>(static_cast<std::size_t>(b.intervals), 1.0));
    const BandPlanckTable own(b, midpoints(b), eps);
    double worst_direct = 0, worst_lookups = 0;
    for (int k = 0; k < 20000; ++k) {
      const double T = std::exp(log_T(rng)), s = unit(rng);
      const double expected = (1.0 - s) * black.direct(T) + s * own.direct(T);
      if (expected < 1e-290) continue;
      const double got = BandPlanckTable::blend(1.0 - s, black, s, own, T);
      worst_direct = std::max(worst_direct, std::abs(got / expected - 1.0));
      const double lookups = (1.0 - s) * black.radiance(T) + s * own.radiance(T);
      worst_lookups = std::max(worst_lookups, std::abs(got / lookups - 1.0));
    }
    EXPECT_LT(worst_direct, 1e-12) << b.low_um << "-" << b.high_um << " um";
    EXPECT_LT(worst_lookups, 1e-14) << b.low_um << "-" << b.high_um << " um";
    for (double T : {5.0, 1200.0, 3000.0})  // off the table: the look-ups' sum
      EXPECT_EQ(BandPlanckTable::blend(0.3, black, 0.7, own, T), 0.3 * black.radiance(T) + 0.7 * own.radiance(T))
          << T;
    for (double T : {12.0, 20.0}) {  // tiny or underflowing (the direct sum there) in the visible
      const double sum = 0.3 * black.radiance(T) + 0.7 * own.radiance(T);
      EXPECT_LE(std::abs(BandPlanckTable::blend(0.3, black, 0.7, own, T) - sum), 1e-14 * sum) << T;
    }
    EXPECT_TRUE(std::isnan(BandPlanckTable::blend(0.3, black, 0.7, own, std::nan(""))));
  }
}

TEST(BandPlanckTable, OffTheTableAndUnderflowAreTheDirectSum) {
  const SpectralBand b{0.45, 0.75, 10};
  const BandPlanckTable table(b, midpoints(b), std::vector<double>(10, 1.0));
  for (double T : {0.0, 5.0, 10.0, 12.0, 20.0, 1200.0, 3000.0})  // 12-20 K: the visible band underflows
    EXPECT_EQ(table.radiance(T), table.direct(T)) << T;
  EXPECT_TRUE(std::isnan(table.radiance(std::nan(""))));
}

}  // namespace
