// Spec 5.2: pixel pitch, IFOV, sample grid and the arctan mapping (eqs. 13-24).
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "sensor/spatial_grid.hpp"
#include "sensor/spectral_grid.hpp"

using namespace eoir::sensor;
using eoir::constants::rad_per_deg;

TEST(SpatialGrid, PitchFromFovInvertsEq21) {
  const double fov = 0.5 * rad_per_deg;
  const double p = pixel_pitch_from_fov_cm(fov, 128, 147.0);
  EXPECT_NEAR(p * 1.0e4, 100.2207, 1.0e-4);  // spec 7.7.1 item e
  EXPECT_NEAR(fov_from_pixel_pitch_rad(p, 128, 147.0), fov, 1.0e-15);
}

TEST(SpatialGrid, IfovEq23) {
  EXPECT_NEAR(ifov_rad(0.01, 100.0), 2.0 * std::atan(0.01 / 200.0), 1e-18);
  EXPECT_NEAR(ifov_rad(0.0100220707, 147.0) * 1000.0, 6.818e-2, 5e-6);
}

TEST(SpatialGrid, SampleIntervalsAndArctanMapping) {
  EXPECT_DOUBLE_EQ(sample_interval_cm(0.01), 0.0025);  // eq. 13
  const AxisGrid g{4, 0.01, 10.0};
  EXPECT_EQ(g.samples(), 16);
  EXPECT_NEAR(g.sample_position_cm(0), -0.02 + 0.00125, 1e-15);
  EXPECT_NEAR(g.sample_position_cm(15), 0.02 - 0.00125, 1e-15);
  EXPECT_NEAR(g.pixel_centre_cm(0), -0.015, 1e-15);
  EXPECT_NEAR(g.sample_position_cm(7) + g.sample_position_cm(8), 0.0, 1e-15);
  // eq. 15: alpha = -arctan(x'/f), and its inverse.
  EXPECT_DOUBLE_EQ(focal_plane_to_angle_rad(1.0, 1.0), -eoir::constants::pi / 4);
  for (double x : {-3.0, -0.01, 0.0, 0.2, 5.0})
    EXPECT_NEAR(angle_to_focal_plane_cm(focal_plane_to_angle_rad(x, 7.0), 7.0), x, 1e-14);
  // Object-space intervals shrink away from the axis (spec 5.2 after eq. 16).
  const double centre = std::abs(g.sample_angle_rad(8) - g.sample_angle_rad(7));
  const double edge = std::abs(g.sample_angle_rad(15) - g.sample_angle_rad(14));
  EXPECT_GT(centre, edge);
  EXPECT_LE(centre, g.sample_interval_cm() / 10.0);  // eq. 17 upper bound
}

TEST(SpectralGrid, Section53) {
  const SpectralGrid s{1.0, 4.0, 10};
  EXPECT_DOUBLE_EQ(s.interval_um(), 0.3);
  EXPECT_DOUBLE_EQ(s.wavelength_um(0), 1.0);
  EXPECT_NEAR(s.wavelength_um(9), 3.7, 1e-15);
  EXPECT_NEAR(s.centre_um(9), 3.85, 1e-15);
  EXPECT_EQ(s.wavelengths_um().size(), 10u);
  EXPECT_NEAR(s.centres_um().front(), 1.15, 1e-15);
}
