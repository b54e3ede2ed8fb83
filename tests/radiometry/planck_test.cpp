// Planck spectral radiance (spec 4.1.5.3 eq. 5), DESIGN.md section 3.
#include "radiometry/planck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace r = eoir::radiometry;

namespace {
bool finite_non_negative(double v) { return std::isfinite(v) && v >= 0.0; }
}  // namespace

TEST(Planck, RadiationConstants) {
  // CODATA 2018 (exact h, c, k): c1L = 2 h c^2 = 1.191042972e-16 W m^2 sr^-1,
  // c2 = 1.438776877e-2 m K, b = 2.897771955e-3 m K.
  EXPECT_NEAR(r::c1L_W_um4_per_cm2_sr / 1.191042972e4, 1.0, 1e-9);
  EXPECT_NEAR(r::c2_um_K / 14387.76877, 1.0, 1e-9);
  EXPECT_NEAR(r::wien_displacement_um_K / 2897.771955, 1.0, 1e-9);
  EXPECT_NEAR(r::stefan_boltzmann_W_per_cm2_K4 / 5.670374419e-12, 1.0, 1e-9);
}

TEST(Planck, KnownValue) {
  // Direct evaluation of eq. 5 at 10 um, 300 K in SI, converted by 1e-10
  // (m^-2 -> cm^-2: 1e-4; per m -> per um: 1e-6).
  const double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23, l = 10e-6, T = 300.0;
  const double si = 2.0 * h * c * c / std::pow(l, 5) / (std::exp(h * c / (l * k * T)) - 1.0);
  EXPECT_NEAR(r::planck_radiance(10.0, 300.0) / (si * 1e-10), 1.0, 1e-13);
  // Commonly quoted: 9.924e-4 W cm^-2 sr^-1 um^-1 (9.924 W m^-2 sr^-1 um^-1).
  EXPECT_NEAR(r::planck_radiance(10.0, 300.0), 9.924e-4, 0.0005e-4);
}

TEST(Planck, WienDisplacementPeakFoundNumerically) {
  for (double T : {3.0, 150.0, 300.0, 1000.0, 5772.0, 1.0e6}) {
    const double expected = 2897.771955 / T;
    // Golden-section maximisation of B over [0.5, 2] * expected.
    double a = 0.5 * expected, b = 2.0 * expected;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a);
    for (int it = 0; it < 200 && (b - a) > 1e-12 * expected; ++it) {
      if (r::planck_radiance(c, T) > r::planck_radiance(d, T)) {
        b = d;
      } else {
        a = c;
      }
      c = b - g * (b - a);
      d = a + g * (b - a);
    }
    const double peak = 0.5 * (a + b);
    EXPECT_NEAR(peak / expected, 1.0, 1e-4) << "T = " << T;
  }
}

TEST(Planck, ExactlyZeroAtAbsoluteZero) {
  for (double l : {1e-3, 0.28, 1.0, 10.0, 28.0, 1e4}) {
    EXPECT_EQ(r::planck_radiance(l, 0.0), 0.0);
    EXPECT_EQ(r::planck_radiance(l, -5.0), 0.0);  // unphysical: also 0
  }
  std::vector<double> grid{0.28, 1.0, 28.0};
  for (double v : r::planck_radiance(0.0, grid)) EXPECT_EQ(v, 0.0);
  EXPECT_EQ(r::planck_radiance(0.0, 300.0), 0.0);
  EXPECT_TRUE(std::isnan(r::planck_radiance(std::nan(""), 300.0)));
}

TEST(Planck, NoOverflowOrNanForAnyLambdaT) {
  // Extremes named by the brief, then a dense sweep of the whole domain.
  EXPECT_TRUE(finite_non_negative(r::planck_radiance(0.28, 3.0)));  // x ~ 1.7e4: underflows to 0
  EXPECT_EQ(r::planck_radiance(0.28, 3.0), 0.0);
  EXPECT_TRUE(finite_non_negative(r::planck_radiance(28.0, 1.0e6)));  // x ~ 5e-4: Rayleigh-Jeans
  // Rayleigh-Jeans limit c1 T / (c2 lambda^4) within x/2 relative.
  const double rj = r::c1L_W_um4_per_cm2_sr * 1.0e6 / (r::c2_um_K * std::pow(28.0, 4));
  EXPECT_NEAR(r::planck_radiance(28.0, 1.0e6) / rj, 1.0, 3e-4);
  EXPECT_TRUE(finite_non_negative(r::planck_radiance(1e-3, 1e-3)));
  EXPECT_TRUE(finite_non_negative(r::planck_radiance(1e-3, 1e6)));
  EXPECT_TRUE(finite_non_negative(r::planck_radiance(1e4, 1e-3)));
  EXPECT_TRUE(finite_non_negative(r::planck_radiance(1e4, 1e6)));
  // Wien side just below the hand-over (x ~ 700, subnormal territory).
  EXPECT_TRUE(finite_non_negative(r::planck_radiance(r::c2_um_K / 700.0, 1.0)));
  EXPECT_TRUE(finite_non_negative(r::planck_radiance(r::c2_um_K / 745.5, 1.0)));
  int checked = 0;
  for (double le = -3.0; le <= 4.0; le += 0.05) {
    for (double te = -3.0; te <= 6.0; te += 0.05) {
      const double v = r::planck_radiance(std::pow(10.0, le), std::pow(10.0, te));
      ASSERT_TRUE(finite_non_negative(v)) << "lambda 1e" << le << " T 1e" << te << " -> " << v;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20000);
}

TEST(Planck, ContinuousAcrossWienHandOver) {
  // The Wien branch starts at x = 40; both sides must agree to rounding.
  const double T = 100.0;
  const double l_at = r::c2_um_K / (40.0 * T);
  const double below = r::planck_radiance(l_at * (1 + 1e-12), T);
  const double above = r::planck_radiance(l_at * (1 - 1e-12), T);
  EXPECT_NEAR(above / below, 1.0, 1e-10);
}

TEST(Planck, VectorisedMatchesScalarAndGrayBody) {
  std::vector<double> grid;
  for (int i = 0; i < 50; ++i) grid.push_back(8.0 + 0.08 * i);
  const auto v = r::planck_radiance(250.0, grid);
  ASSERT_EQ(v.size(), grid.size());
  std::vector<double> acc(grid.size(), 1.0);
  r::add_gray_body_radiance(0.25, 250.0, grid.data(), acc.data(), acc.size());
  std::vector<double> in_place = grid;
  r::planck_radiance(250.0, in_place.data(), in_place.data(), in_place.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    EXPECT_EQ(v[i], r::planck_radiance(grid[i], 250.0));
    EXPECT_EQ(in_place[i], v[i]);
    EXPECT_DOUBLE_EQ(acc[i], 1.0 + 0.25 * v[i]);
    EXPECT_DOUBLE_EQ(r::gray_body_radiance(0.4, grid[i], 250.0), 0.4 * v[i]);
  }
}
