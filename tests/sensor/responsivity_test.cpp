// Spec 5.4-5.5: responsivities (eqs. 26-32).
#include <gtest/gtest.h>

#include "core/constants.hpp"
#include "sensor/responsivity.hpp"

using namespace eoir::sensor;

TEST(Responsivity, Eq31ByHand) {
  // pi A_d 0.8 lambda_low t / ((4 F^2 + 1) h c): 50 um pixels, F/2, 3 um, 5 ms.
  const double hc = 6.62607015e-34 * 2.99792458e10;
  const double expected = eoir::constants::pi * (0.005 * 0.005) * 0.8 * 3e-4 * 5e-3 / (17.0 * hc);
  EXPECT_NEAR(peak_radiance_responsivity(0.005, 0.005, 2.0, 3.0, 5.0) / expected, 1.0, 1e-14);
}

TEST(Responsivity, BoxcarRsr) {
  EXPECT_EQ(radiance_responsivity(0.99, 1.0, 4.0, 7.0), 0.0);
  EXPECT_EQ(radiance_responsivity(2.0, 1.0, 4.0, 7.0), 7.0);
  EXPECT_EQ(radiance_responsivity(4.01, 1.0, 4.0, 7.0), 0.0);
}

TEST(Responsivity, Eq32) {
  EXPECT_DOUBLE_EQ(peak_irradiance_responsivity(2.0, 0.5, 1e-3, 2e-3), 2.0 * 0.5 / 2e-6);
}
