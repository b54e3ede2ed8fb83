// Columns along paths through the shells (issue 20 items 2 and 9; spec
// 4.3.1.1, 6.2.5.4): the relative air mass against Kasten and Young (1989),
// paths in either direction, on the ellipsoid at the pole and the equator,
// paths above the atmosphere, grazing the limb, from aircraft and from the
// top of the atmosphere.
#include <gtest/gtest.h>

#include <cmath>

#include "atmosphere/profile.hpp"
#include "atmosphere/shell_path.hpp"
#include "core/constants.hpp"
#include "core/data_dir.hpp"

namespace eoir::atmosphere {
namespace {

std::shared_ptr<const AtmosphereProfile> us76() {
  universe::AtmosphereSettings s;
  s.model = universe::AtmosphereModel::simple;
  s.aerosol = universe::AerosolModel::rural;
  return AtmosphereProfile::make(s, resolve_data_dir(""));
}

const EarthFigure kEarth;
const double a = kEarth.equatorial_radius_m, b = kEarth.polar_radius_m;

// A point at geodetic latitude 0 (longitude 0) and altitude h, and the
// direction at zenith angle z in the meridian plane.
Vec3 equator(double h) { return Vec3(a + h, 0, 0); }
Vec3 zenith_direction(double z_deg) {
  const double z = z_deg * constants::rad_per_deg;
  return Vec3(std::cos(z), 0, std::sin(z));
}

// Kasten and Young (1989), Applied Optics 28, 4735: m = 1 / (cos z + 0.50572
// (96.07995 - z)^-1.6364), z in degrees.
double kasten_young(double z_deg) {
  return 1.0 / (std::cos(z_deg * constants::rad_per_deg) + 0.50572 * std::pow(96.07995 - z_deg, -1.6364));
}

TEST(ShellPath, RelativeAirMassAgainstKastenYoung) {
  const auto p = us76();
  const double vertical = path_to_space(*p, kEarth, equator(0), zenith_direction(0)).air_m2;
  EXPECT_NEAR(vertical / p->vertical_columns_above(0).air_m2, 1.0, 1e-6);
  // Kasten and Young's argument is the apparent zenith angle (their tables
  // follow the refracted ray): the column along the refracted ray.
  for (double z = 0; z <= 85.0; z += 2.5) {
    bool ground = true;
    const double m = refracted_path_to_space(*p, kEarth, equator(0), zenith_direction(z), ground).air_m2 / vertical;
    EXPECT_FALSE(ground);
    EXPECT_NEAR(m / kasten_young(z), 1.0, 0.01) << "zenith angle " << z << ": " << m << " vs " << kasten_young(z);
  }
  // The straight ray at 85 deg passes through 1 % less air; at the horizon
  // the refracted column is finite (Kasten and Young: 38.09).
  const double straight85 = path_to_space(*p, kEarth, equator(0), zenith_direction(85)).air_m2 / vertical;
  EXPECT_NEAR(straight85 / kasten_young(85), 0.99, 0.005);
  bool ground = true;
  const double horizon = refracted_path_to_space(*p, kEarth, equator(0), zenith_direction(90), ground).air_m2 / vertical;
  EXPECT_FALSE(ground);
  EXPECT_NEAR(horizon / 38.09, 1.0, 0.05) << horizon;
  // Below the horizon from a mountain the ray passes a lowest point and
  // climbs again; further down it meets the ground.
  const double from_3km = refracted_path_to_space(*p, kEarth, equator(3000), zenith_direction(91), ground).air_m2;
  EXPECT_FALSE(ground);
  EXPECT_TRUE(std::isfinite(from_3km) && from_3km > p->vertical_columns_above(3000).air_m2 * 20);
  refracted_path_to_space(*p, kEarth, equator(3000), zenith_direction(95), ground);
  EXPECT_TRUE(ground);
}

// The same path in either direction; a satellite's line of sight to the
// ground equals the ground's to the satellite's height.
TEST(ShellPath, EitherDirection) {
  const auto p = us76();
  const Vec3 ground = equator(0), sat = equator(0) + 2000e3 * zenith_direction(60);
  const PathColumns up = path_between(*p, kEarth, ground, sat), down = path_between(*p, kEarth, sat, ground);
  EXPECT_NEAR(up.air_m2 / down.air_m2, 1.0, 1e-12);
  EXPECT_NEAR(up.h2o_m2 / down.h2o_m2, 1.0, 1e-12);
  EXPECT_NEAR(up.aerosol_tau_550 / down.aerosol_tau_550, 1.0, 1e-12);
  const PathColumns space = path_to_space(*p, kEarth, ground, zenith_direction(60));
  EXPECT_NEAR(up.air_m2 / space.air_m2, 1.0, 1e-9);
  EXPECT_NEAR(up.o3_m2 / space.o3_m2, 1.0, 1e-9);
}

// The shells follow the ellipsoid: the vertical column at the pole equals
// the equator's (the same profile above the surface).
TEST(ShellPath, ShellsFollowTheEllipsoid) {
  const auto p = us76();
  const double equatorial = path_to_space(*p, kEarth, equator(0), Vec3::UnitX()).air_m2;
  const double polar = path_to_space(*p, kEarth, Vec3(0, 0, b), Vec3::UnitZ()).air_m2;
  EXPECT_NEAR(polar / equatorial, 1.0, 1e-4);
  EXPECT_NEAR(altitude_m(kEarth, Vec3(0, 0, b + 10000)), 10000.0, 1.0);
  const Vec3 n45 = Vec3(std::cos(0.7853981633974483), 0, std::sin(0.7853981633974483));
  // 45 deg geodetic latitude: the surface point of WGS84 and its normal.
  const double phi = 0.7853981633974483, e2 = 1 - (b * b) / (a * a);
  const double N = a / std::sqrt(1 - e2 * std::sin(phi) * std::sin(phi));
  const Vec3 surface(N * std::cos(phi), 0, N * (1 - e2) * std::sin(phi));
  EXPECT_NEAR(altitude_m(kEarth, surface + 5000.0 * n45), 5000.0, 15.0);
}

// Nothing above the atmosphere: no crossing, no cost. A sensor at the top
// of the atmosphere looking down sees the whole column; grazing paths that
// never touch the ground are finite, symmetric and continuous in the
// tangent height; an aircraft at 10 km sees the column above it.
TEST(ShellPath, AboveGrazingTopAndAircraft) {
  const auto p = us76();
  const PathColumns above = path_between(*p, kEarth, equator(200e3), equator(200e3) + Vec3(0, 1e6, 0));
  EXPECT_FALSE(above.crosses);
  EXPECT_EQ(above.air_m2, 0.0);
  const PathColumns top = path_between(*p, kEarth, equator(100e3 - 1e-3), equator(0));
  EXPECT_NEAR(top.air_m2 / p->vertical_columns_above(0).air_m2, 1.0, 1e-6);
  double previous = 0;
  for (double h = 0.0; h < 100e3; h += 500.0) {
    // A horizontal line whose tangent point is at height h over the equator.
    const Vec3 tangent = equator(h);
    const PathColumns g = path_between(*p, kEarth, tangent + Vec3(0, -3000e3, 0), tangent + Vec3(0, 3000e3, 0));
    EXPECT_TRUE(std::isfinite(g.air_m2) && std::isfinite(g.aerosol_tau_550));
    EXPECT_NEAR(g.lowest_altitude_m, h, 1.0);
    const PathColumns half = path_between(*p, kEarth, tangent, tangent + Vec3(0, 3000e3, 0));
    EXPECT_NEAR(2.0 * half.air_m2, g.air_m2, 1e-9 * g.air_m2 + 1e-30);
    if (h > 0) {
      EXPECT_LT(g.air_m2, previous * 1.0000001);
    }
    if (h > 0 && h < 80e3) {
      EXPECT_GT(g.air_m2, 0.3 * previous);  // no jump between neighbours 500 m apart
    }
    previous = g.air_m2;
  }
  const double aircraft = path_to_space(*p, kEarth, equator(10e3), Vec3::UnitX()).air_m2;
  EXPECT_NEAR(aircraft / p->vertical_columns_above(10e3).air_m2, 1.0, 1e-6);
}

// The segments add to the totals and carry the layers' temperatures.
TEST(ShellPath, SegmentsAddUp) {
  const auto p = us76();
  const PathColumns c = path_to_space(*p, kEarth, equator(0), zenith_direction(70), true);
  double air = 0, length = 0;
  for (const PathSegment& s : c.segments) {
    air += s.air_m2;
    length += s.length_m;
    EXPECT_GT(s.temperature_K, 180.0);
    EXPECT_LT(s.temperature_K, 290.0);
  }
  EXPECT_NEAR(air / c.air_m2, 1.0, 1e-12);
  EXPECT_NEAR(length / c.length_m, 1.0, 1e-12);
  EXPECT_GE(c.segments.size(), p->levels().size() - 1);
}


// A refracted ray leaving a mountain below the horizon: its segments run
// from the observer out (down to the lowest point, then up), as the
// Schwarzschild sum of path_optics needs.
TEST(ShellPath, DescendingRefractedSegmentsRunFromTheObserver) {
  const auto p = us76();
  bool ground = true;
  const PathColumns c = refracted_path_to_space(*p, kEarth, equator(3000), zenith_direction(91), ground);
  ASSERT_FALSE(ground);
  ASSERT_GT(c.segments.size(), 4u);
  EXPECT_EQ(c.segments.front().layer, p->layer_of(2999.0));
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < c.segments.size(); ++k)
    if (c.segments[k].layer < c.segments[lowest].layer) lowest = k;
  for (std::size_t k = 1; k <= lowest; ++k) EXPECT_LE(c.segments[k].layer, c.segments[k - 1].layer) << k;
  for (std::size_t k = lowest + 1; k < c.segments.size(); ++k) EXPECT_GE(c.segments[k].layer, c.segments[k - 1].layer) << k;
  EXPECT_EQ(c.segments.back().layer, p->levels().size() - 2);
}

}  // namespace
}  // namespace eoir::atmosphere
