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

TEST(BandPlanckTable, OffTheTableAndUnderflowAreTheDirectSum) {
  const SpectralBand b{0.45, 0.75, 10};
  const BandPlanckTable table(b, midpoints(b), std::vector<double>(10, 1.0));
  for (double T : {0.0, 5.0, 10.0, 12.0, 20.0, 1200.0, 3000.0})  // 12-20 K: the visible band underflows
    EXPECT_EQ(table.radiance(T), table.direct(T)) << T;
  EXPECT_TRUE(std::isnan(table.radiance(std::nan(""))));
}

}  // namespace
