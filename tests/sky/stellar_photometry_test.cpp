// Stellar photometry (spec 4.1.6.1): E = m0 B(T), T from B-V (Ballesteros
// 2012), m0 from the V zero point (Bessell, Castelli & Plez 1998); the
// Pollux benchmark of spec 6.2.5.2 and its ERRATA row.
#include "radiometry/stellar_photometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "radiometry/planck.hpp"

namespace r = eoir::radiometry;

// Ballesteros (2012) eq. 14 at the Sun's B-V = 0.65 gives 5778 K, within
// 0.2 % of the Sun's nominal effective temperature 5772 K (IAU 2015 B3),
// as the paper states for the Sun; B-V = 0 (Vega-like) gives 10125 K.
TEST(StellarPhotometry, BallesterosTemperatureFromBV) {
  EXPECT_NEAR(r::temperature_from_b_v(0.65), 5772.0, 0.002 * 5772.0);
  EXPECT_NEAR(r::temperature_from_b_v(0.65), 5778.4, 0.1);
  EXPECT_NEAR(r::temperature_from_b_v(0.0), 10125.3, 0.1);
  EXPECT_NEAR(r::temperature_from_b_v(1.0), 4742.7, 0.1);   // Pollux-like K0 III
  EXPECT_NEAR(r::temperature_from_b_v(1.5), 3793.5, 0.1);   // M0-like
  // The closed-form inverse of eq. 14 (the quadratic in B-V) recovers B-V.
  for (double bv = -0.3; bv <= 1.95; bv += 0.05) {
    const double d = r::temperature_from_b_v(bv) / 4600.0;
    const double a = 0.92, b = 1.70, c = 0.62;
    const double back = (2.0 - d * (b + c) + std::sqrt(4.0 + (b - c) * (b - c) * d * d)) / (2.0 * a * d);
    EXPECT_NEAR(back, bv, 1e-12);
  }
  // Monotonic, clamped outside [-0.4, 2.0], non-finite rejected.
  EXPECT_GT(r::temperature_from_b_v(0.2), r::temperature_from_b_v(0.3));
  EXPECT_DOUBLE_EQ(r::temperature_from_b_v(3.0), r::temperature_from_b_v(2.0));
  EXPECT_FALSE(r::b_v_in_range(3.0));
  EXPECT_THROW(r::temperature_from_b_v(std::nan("")), eoir::Error);
}

// V = 0 gives 3.631e-12 W cm^-2 um^-1 at 0.55 um: exact (1e-12 relative) with
// the monochromatic calibration for any colour; with the V-passband
// calibration the passband mean is exact and E(0.55 um) of a B-V = 0 star is
// 3.611e-12, 0.6 % low (tolerance 1 %: a 10125 K blackbody's mean over V sits
// slightly blueward of 0.55 um).
TEST(StellarPhotometry, VZeroGivesTheBesselZeroPoint) {
  for (double bv : {-0.2, 0.0, 0.65, 1.0, 1.8}) {
    EXPECT_NEAR(r::stellar_spectral_irradiance(0.55, 0.0, bv), 3.631e-12, 3.631e-24) << bv;
    EXPECT_NEAR(r::v_passband_mean_irradiance(0.0, bv, r::VZeroPoint::v_passband_mean), 3.631e-12, 3.631e-24) << bv;
  }
  const double e055 = r::stellar_spectral_irradiance(0.55, 0.0, 0.0, r::VZeroPoint::v_passband_mean);
  EXPECT_NEAR(e055, 3.631e-12, 0.01 * 3.631e-12);
  std::printf("V=0, B-V=0: E(0.55 um) = %.4e (passband calibration)\n", e055);
  // Five magnitudes = factor 100; m0 = E / B.
  EXPECT_NEAR(r::stellar_spectral_irradiance(0.55, 5.0, 0.3) / r::stellar_spectral_irradiance(0.55, 0.0, 0.3), 0.01, 1e-14);
  const double T = r::temperature_from_b_v(0.3);
  EXPECT_NEAR(r::m0_sr(2.0, T) * r::planck_radiance(1.3, T), r::stellar_spectral_irradiance(1.3, 2.0, 0.3), 1e-25);
  // The exact band integral equals a fine numerical sum.
  double sum = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) sum += r::stellar_spectral_irradiance(0.3 + (i + 0.5) * 5.0 / n, 1.15, 1.0) * 5.0 / n;
  EXPECT_NEAR(r::stellar_band_irradiance(0.3, 5.3, 1.15, 1.0), sum, 1e-6 * sum);
  EXPECT_THROW(r::m0_sr(0.0, 0.0), eoir::Error);
  EXPECT_THROW(r::m0_sr(std::nan(""), 5000.0), eoir::Error);
}

TEST(StellarPhotometry, BessellVResponse) {
  EXPECT_DOUBLE_EQ(r::bessell_v_response(0.53), 1.0);
  EXPECT_NEAR(r::bessell_v_response(0.50), 0.458, 1e-12);
  EXPECT_NEAR(r::bessell_v_response(0.505), 0.5 * (0.458 + 0.780), 1e-12);
  EXPECT_DOUBLE_EQ(r::bessell_v_response(0.46), 0.0);
  EXPECT_DOUBLE_EQ(r::bessell_v_response(0.71), 0.0);
}

// Spec 6.2.5.2: EOIR shows 3.294e-12 W cm^-2 um^-1 at 0.6 um for Pollux
// (V = 1.15, T = 4937.9 K). Standard photometry (ERRATA) gives ~1.3e-12:
// with B-V = 1.00 (T = 4743 K) we get 1.29e-12 (monochromatic) and
// 1.30e-12 (passband); with the spec's own 4937.9 K, 1.27e-12. The spec's
// value is 2.5x (1.0 mag) brighter than the V magnitude allows.
TEST(StellarPhotometry, PolluxBenchmark) {
  const double mono = r::stellar_spectral_irradiance(0.6, 1.15, 1.00);
  const double band = r::stellar_spectral_irradiance(0.6, 1.15, 1.00, r::VZeroPoint::v_passband_mean);
  const double spec_T = r::m0_sr(1.15, 4937.9) * r::planck_radiance(0.6, 4937.9);
  std::printf("Pollux E(0.6 um): %.4e (0.55 um cal.), %.4e (V passband), %.4e (T = 4937.9 K); spec 3.294e-12, "
              "ratio spec/ours %.3f\n",
              mono, band, spec_T, 3.294e-12 / mono);
  EXPECT_NEAR(mono, 1.3e-12, 0.05e-12);
  EXPECT_NEAR(band, 1.3e-12, 0.05e-12);
  EXPECT_NEAR(spec_T, 1.3e-12, 0.05e-12);
  EXPECT_GT(3.294e-12 / mono, 2.4);
  EXPECT_LT(3.294e-12 / mono, 2.7);
}
