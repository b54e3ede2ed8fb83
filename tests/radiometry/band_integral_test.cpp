// Band integrals: the spec 5.3 grid and its quadrature, the exact
// (series) Planck band integral, gray bodies; spec numbers of 7.3 / 7.4.2.
#include "radiometry/band_integral.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "radiometry/planck.hpp"

namespace r = eoir::radiometry;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Reference: composite Gauss-Legendre (5 points) on many sub-intervals.
double reference_band(double T, double low, double high, int pieces = 4000) {
  static const double xg[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const double wg[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                               0.2369268850561891};
  const double h = (high - low) / pieces;
  double sum = 0.0;
  for (int p = 0; p < pieces; ++p) {
    const double mid = low + (p + 0.5) * h;
    for (int j = 0; j < 5; ++j) sum += wg[j] * r::planck_radiance(mid + 0.5 * h * xg[j], T);
  }
  return sum * 0.5 * h;
}
}  // namespace

TEST(BandGrid, SpecGridAndSampleWavelengths) {
  const r::SpectralBand band{8.0, 12.0, 4};
  EXPECT_DOUBLE_EQ(band.interval_um(), 1.0);
  EXPECT_EQ(band.grid_wavelengths_um(), (std::vector<double>{8.0, 9.0, 10.0, 11.0}));  // spec 5.3
  EXPECT_EQ(band.sample_wavelengths_um(r::SpectralQuadrature::interval_left_edge), band.grid_wavelengths_um());
  EXPECT_EQ(band.sample_wavelengths_um(r::SpectralQuadrature::interval_midpoint),
            (std::vector<double>{8.5, 9.5, 10.5, 11.5}));
  EXPECT_EQ(band.sample_wavelengths_um(), band.sample_wavelengths_um(r::kDefaultSpectralQuadrature));
  EXPECT_EQ(r::kDefaultSpectralQuadrature, r::SpectralQuadrature::interval_midpoint);
  EXPECT_DOUBLE_EQ(r::integrate_spectral_samples(band, {1.0, 2.0, 3.0, 4.0}), 10.0);
  EXPECT_THROW(r::integrate_spectral_samples(band, {1.0, 2.0}), eoir::Error);
  EXPECT_THROW((r::SpectralBand{12.0, 8.0, 4}.validate()), eoir::Error);
  EXPECT_THROW((r::SpectralBand{8.0, 12.0, 0}.validate()), eoir::Error);
  EXPECT_THROW((r::SpectralBand{0.0, 12.0, 5}.validate()), eoir::Error);
}

TEST(BoseEinstein, SeriesAgreeAtHandOverAndSumToPi4Over15) {
  const double total = std::pow(kPi, 4) / 15.0;
  for (double x : {0.0, 1e-8, 0.01, 0.5, 0.999999, 1.0, 1.000001, 2.0, 5.0, 30.0}) {
    EXPECT_NEAR(r::bose_einstein_upper3(x) + r::bose_einstein_lower3(x), total, 4e-15 * total) << x;
  }
  EXPECT_EQ(r::bose_einstein_upper3(kInf), 0.0);
  EXPECT_EQ(r::bose_einstein_lower3(0.0), 0.0);
  EXPECT_DOUBLE_EQ(r::bose_einstein_upper3(0.0), total);
  // Small x: lower ~ x^3/3 - x^4/8 + x^5/60 - ...
  EXPECT_NEAR(r::bose_einstein_lower3(1e-3) / (1e-9 / 3.0 - 1e-12 / 8.0 + 1e-15 / 60.0), 1.0, 1e-13);
  // Large x: upper ~ e^-x (x^3 + 3x^2 + 6x + 6).
  const double x = 50.0;
  EXPECT_NEAR(r::bose_einstein_upper3(x) / (std::exp(-x) * (x * x * x + 3 * x * x + 6 * x + 6)), 1.0, 1e-15);
  // Either side of x = 1, the two evaluations agree with a numerical integral.
  for (double xs : {0.9, 1.0, 1.1}) {
    // int_xs^40 by Simpson on t^3/(e^t-1), plus the negligible tail.
    const int n = 20000;
    const double h = (40.0 - xs) / n;
    auto f = [](double t) { return t * t * t / std::expm1(t); };
    double s = f(xs) + f(40.0);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(xs + i * h);
    s *= h / 3.0;
    s += r::bose_einstein_upper3(40.0);
    EXPECT_NEAR(r::bose_einstein_upper3(xs) / s, 1.0, 1e-12) << xs;
  }
}

TEST(PlanckBand, StefanBoltzmannTotal) {
  // int_0^inf B d lambda = sigma T^4 / pi, sigma = 5.670374419e-8 W m^-2 K^-4
  // = 5.670374419e-12 W cm^-2 K^-4.
  for (double T : {1.0, 3.0, 77.0, 150.0, 300.0, 5772.0, 1.0e6}) {
    const double expected = 5.670374419e-12 * std::pow(T, 4) / kPi;
    EXPECT_NEAR(r::planck_band_radiance(T, 0.0, kInf) / expected, 1.0, 1e-9) << T;
    // Split anywhere, the two halves add up to the total (compared with the
    // unrounded sigma = 5.670374419184429e-8; the quoted 10-digit value is
    // 3.3e-11 low).
    const double exact_total = r::stefan_boltzmann_W_per_cm2_K4 * std::pow(T, 4) / kPi;
    EXPECT_NEAR(r::planck_band_radiance(T, 0.0, kInf) / exact_total, 1.0, 1e-14) << T;
    for (double split : {0.1 * 2897.771955 / T, 2897.771955 / T, 10.0 * 2897.771955 / T}) {
      const double sum = r::planck_band_radiance(T, 0.0, split) + r::planck_band_radiance(T, split, kInf);
      EXPECT_NEAR(sum / exact_total, 1.0, 1e-14) << T << " " << split;
    }
  }
}

TEST(PlanckBand, SpecValidationNumbers) {
  // 7.3: "the true band-integrated radiance for the Planck function at 150 K
  // from 8-12 um is 3.40E-5 W/(cm^2 sr)" (ERRATA confirms). Ours: 3.39987e-5.
  const double l150 = r::planck_band_radiance(150.0, 8.0, 12.0);
  EXPECT_NEAR(l150, 3.40e-5, 0.005e-5);
  // 7.4.2: 200 K, 8-12 um: 3.481E-4. Ours: 3.48102e-4.
  const double l200 = r::planck_band_radiance(200.0, 8.0, 12.0);
  EXPECT_NEAR(l200, 3.481e-4, 0.0005e-4);
  std::printf("exact 8-12 um: 150 K %.6e, 200 K %.6e, 300 K %.6e W cm^-2 sr^-1\n", l150, l200,
              r::planck_band_radiance(300.0, 8.0, 12.0));
}

TEST(PlanckBand, MatchesHighOrderQuadratureAcrossRegimes) {
  struct Case {
    double T, low, high;
  };
  // Both series regimes and the mixed one (x = 1 inside the band), and the
  // spec's full 0.28-28 um range at extreme temperatures.
  const Case cases[] = {{150, 8, 12},     {200, 8, 12},    {300, 8, 12},    {300, 3, 5},          {5772, 0.28, 1},
                        {5772, 0.4, 0.7}, {1e4, 1, 4},     {1e4, 0.28, 28}, {1e6, 0.28, 28},      {1e6, 8, 12},
                        {3, 0.28, 28},    {3, 100, 10000}, {2000, 7, 7.2},  {14387.76877, 0.5, 2}};
  for (const auto& c : cases) {
    const double exact = r::planck_band_radiance(c.T, c.low, c.high);
    const double ref = reference_band(c.T, c.low, c.high);
    ASSERT_TRUE(std::isfinite(exact));
    if (ref == 0.0) {
      EXPECT_EQ(exact, 0.0);
    } else {
      EXPECT_NEAR(exact / ref, 1.0, 1e-11) << c.T << " K " << c.low << "-" << c.high;
    }
  }
}

TEST(PlanckBand, ZeroAtAbsoluteZeroAndExtremesFinite) {
  EXPECT_EQ(r::planck_band_radiance(0.0, 8.0, 12.0), 0.0);
  EXPECT_EQ(r::planck_band_radiance(0.0, 0.0, kInf), 0.0);
  EXPECT_EQ(r::gray_body_band_radiance(0.7, 0.0, 0.28, 28.0), 0.0);
  EXPECT_EQ(r::grid_planck_band_radiance(0.0, {8.0, 12.0, 50}), 0.0);
  EXPECT_EQ(r::planck_band_radiance(300.0, 10.0, 10.0), 0.0);
  // 0.28 um at 3 K: x ~ 1.7e4, underflows to exactly 0, no NaN.
  EXPECT_EQ(r::planck_band_radiance(3.0, 0.28, 0.3), 0.0);
  for (double T : {1e-3, 3.0, 1e6}) {
    for (double lo : {1e-3, 0.28, 28.0}) {
      for (double hi : {0.3, 28.0, 1e4, kInf}) {
        if (hi < lo) continue;
        const double v = r::planck_band_radiance(T, lo, hi);
        EXPECT_TRUE(std::isfinite(v) && v >= 0.0) << T << " " << lo << " " << hi << " " << v;
      }
    }
  }
  EXPECT_THROW(r::planck_band_radiance(-1.0, 8.0, 12.0), eoir::Error);
  EXPECT_THROW(r::planck_band_radiance(300.0, 12.0, 8.0), eoir::Error);
  EXPECT_THROW(r::planck_band_radiance(std::nan(""), 8.0, 12.0), eoir::Error);
  EXPECT_THROW(r::planck_band_radiance(300.0, 8.0, std::nan("")), eoir::Error);
}

TEST(PlanckBand, GrayBodyLinearInEmissivity) {
  const double bb = r::planck_band_radiance(250.0, 8.0, 12.0);
  for (double eps : {0.0, 0.1, 0.35, 0.5, 0.9, 1.0}) {
    EXPECT_DOUBLE_EQ(r::gray_body_band_radiance(eps, 250.0, 8.0, 12.0), eps * bb);
  }
  const double a = r::gray_body_band_radiance(0.2, 250.0, 8.0, 12.0);
  const double b = r::gray_body_band_radiance(0.6, 250.0, 8.0, 12.0);
  EXPECT_NEAR(a + b, r::gray_body_band_radiance(0.8, 250.0, 8.0, 12.0), 1e-15 * bb);
  // 7.3 sets "Gray Body" with reflectance 0 %: emissivity 1, a blackbody.
  EXPECT_EQ(r::emissivity_from_reflectance(0.0), 1.0);
  EXPECT_DOUBLE_EQ(r::emissivity_from_reflectance(0.25), 0.75);
  EXPECT_THROW(r::emissivity_from_reflectance(1.5), eoir::Error);
  EXPECT_THROW(r::gray_body_band_radiance(-0.1, 250.0, 8.0, 12.0), eoir::Error);
  // Sample vectors are linear too: eps * B on the grid integrates to eps * grid sum.
  const r::SpectralBand band{8.0, 12.0, 25};
  auto v = r::planck_radiance(250.0, band.sample_wavelengths_um());
  for (auto& x : v) x *= 0.3;
  EXPECT_NEAR(r::integrate_spectral_samples(band, v), 0.3 * r::grid_planck_band_radiance(250.0, band), 1e-15 * bb);
}

// Spec 7.3: band-integrated radiance on the grid vs. the number of intervals.
// Measured relative errors (grid - exact) / exact, 8-12 um:
//
//   N    150 K mid  150 K left  200 K mid  200 K left  300 K mid  300 K left
//   6    -0.1128 %  -13.418 %   +0.0668 %  -7.252 %    +0.0885 %  -0.076 %
//   12   -0.0282 %   -6.765 %   +0.0167 %  -3.593 %    +0.0221 %  +0.006 %
//   25   -0.0065 %   -3.261 %   +0.0038 %  -1.716 %    +0.0051 %  +0.014 %
//   50   -0.0016 %   -1.634 %   +0.0010 %  -0.856 %    +0.0013 %  +0.010 %
//   75   -0.0007 %   -1.090 %   +0.0004 %  -0.570 %    +0.0006 %  +0.007 %
//   100  -0.0004 %   -0.818 %   +0.0002 %  -0.428 %    +0.0003 %  +0.005 %
//
// The midpoint (default) error falls as 1/N^2 and is within 0.5 % already at
// N = 6; the literal left-edge grid falls as 1/N and is NOT within 0.5 % at
// N = 100 for 150 K (B rises ~7x across 8-12 um at 150 K). At 300 K the band
// straddles the Planck peak (9.66 um) so the left-edge first-order terms
// nearly cancel and its error is small but not monotone.
TEST(GridBand, ConvergesToExactAsIntervalsGrow) {
  const int Ns[] = {6, 12, 25, 50, 75, 100};
  for (double T : {150.0, 200.0, 300.0}) {
    const double exact = r::planck_band_radiance(T, 8.0, 12.0);
    double prev_mid = kInf, prev_left = kInf, first_left = 0.0;
    for (int N : Ns) {
      const r::SpectralBand band{8.0, 12.0, N};
      const double mid = r::grid_planck_band_radiance(T, band, r::SpectralQuadrature::interval_midpoint);
      const double left = r::grid_planck_band_radiance(T, band, r::SpectralQuadrature::interval_left_edge);
      const double e_mid = mid / exact - 1.0, e_left = left / exact - 1.0;
      std::printf("T %5.0f K  N %3d  midpoint %+.4f %%  left edge %+.3f %%\n", T, N, 100 * e_mid, 100 * e_left);
      // Midpoint: strictly monotone convergence, second order.
      EXPECT_LT(std::fabs(e_mid), prev_mid) << T << " " << N;
      EXPECT_LT(std::fabs(e_mid) * N * N, 45.0) << T << " " << N;  // |e| N^2 ~ 40 (150 K), 24, 32
      EXPECT_LT(std::fabs(e_mid), 0.005);
      if (N == 100) {
        EXPECT_LT(std::fabs(e_mid), 5e-6);
      }
      // Left edge: first order; monotone where the band is on one side of
      // the peak (150, 200 K), never worse than at N = 6 otherwise.
      if (T < 250.0) {
        EXPECT_LT(std::fabs(e_left), prev_left) << T << " " << N;
        EXPECT_NEAR(std::fabs(e_left) * N, T == 150.0 ? 0.81 : 0.43, 0.03) << T << " " << N;
      } else {
        if (N == 6) first_left = std::fabs(e_left);
        EXPECT_LE(std::fabs(e_left), std::max(first_left, 2e-4)) << T << " " << N;
      }
      if (N == 100) {
        EXPECT_LT(std::fabs(e_left), 0.01);
      }
      prev_mid = std::fabs(e_mid);
      prev_left = std::fabs(e_left);
    }
  }
}

TEST(GridBand, ExactIntegralIndependentOfIntervals) {
  // DESIGN.md 3: the exact Planck band value does not depend on N; the grid
  // sum of 7.4.2's N = 50 reproduces 3.481e-4 at 200 K with the default rule.
  EXPECT_NEAR(r::grid_planck_band_radiance(200.0, {8.0, 12.0, 50}), 3.481e-4, 0.0005e-4);
  EXPECT_NEAR(r::grid_planck_band_radiance(150.0, {8.0, 12.0, 50}), 3.40e-5, 0.005e-5);
}
