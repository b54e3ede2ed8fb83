// Rotational elements of the central bodies (IAU WGCCRE): the Moon keeps its
// mean-Earth meridian toward the Earth within its optical libration, the
// poles point where the elements say.
#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "universe/central_bodies.hpp"
#include "universe/rotation_models.hpp"

namespace u = eoir::universe;

// The sub-Earth point of the Moon stays within the optical libration (7.9
// deg in longitude, 6.9 deg in latitude; e.g. Meeus, Astronomical
// Algorithms, ch. 53) of the mean-Earth origin, every 5 days over a year.
TEST(RotationModels, MoonFacesTheEarthWithinItsLibration) {
  const eoir::EngineTime t0 = eoir::EngineTime::from(eoir::utc_from_iso("2010-01-01T00:00:00Z"));
  double max_lon = 0, max_lat = 0;
  for (int day = 0; day < 365; day += 5) {
    const eoir::EngineTime t = t0.plus_seconds(day * 86400.0);
    eoir::frames::Vec3 r, v;
    u::central_body_state_j2000(u::central_body_info(u::CentralBody::moon), t, r, v);
    const Eigen::Vector3d earth_body = u::body_to_j2000(u::CentralBody::moon, t).transpose() * (-r).normalized();
    const double lon = std::atan2(earth_body.y(), earth_body.x()) * eoir::constants::deg_per_rad;
    const double lat = std::asin(earth_body.z()) * eoir::constants::deg_per_rad;
    max_lon = std::max(max_lon, std::fabs(lon));
    max_lat = std::max(max_lat, std::fabs(lat));
  }
  EXPECT_LT(max_lon, 8.5);
  EXPECT_LT(max_lat, 7.5);
  EXPECT_GT(max_lon, 4.0);  // libration is seen
  EXPECT_GT(max_lat, 4.0);
}

// The body's z axis is the pole of its elements: Mars at J2000.0
// (alpha0 317.68143 deg, delta0 52.88650 deg; Archinal et al. 2011 Table 1).
TEST(RotationModels, PoleAndRightHandedAxes) {
  const eoir::EngineTime j2000 = eoir::EngineTime::from_tt_days(0.0, 0.0);
  const Eigen::Matrix3d m = u::body_to_j2000(u::CentralBody::mars, j2000);
  const double ra = 317.68143 * eoir::constants::rad_per_deg, dec = 52.88650 * eoir::constants::rad_per_deg;
  const Eigen::Vector3d pole(std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec));
  EXPECT_NEAR((m.col(2) - pole).norm(), 0.0, 1e-6);  // TDB - TT shifts T by < 2 ms
  EXPECT_NEAR(m.determinant(), 1.0, 1e-12);
  EXPECT_NEAR((m.transpose() * m - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
}
