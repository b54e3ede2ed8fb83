// Refraction and the aerosol's spectra (issue 20 items 1, 6, 9).
#include <gtest/gtest.h>

#include <cmath>

#include "atmosphere/aerosol_optics.hpp"
#include "atmosphere/profile.hpp"
#include "atmosphere/refraction.hpp"
#include "atmosphere/shell_path.hpp"
#include "core/constants.hpp"
#include "core/data_dir.hpp"
#include "core/error.hpp"

namespace eoir::atmosphere {
namespace {

constexpr double kArcsec = constants::pi / (180.0 * 3600.0);

std::shared_ptr<const AtmosphereProfile> us76() {
  universe::AtmosphereSettings s;
  s.model = universe::AtmosphereModel::simple;
  s.aerosol = universe::AerosolModel::none;
  return AtmosphereProfile::make(s, resolve_data_dir(""));
}

// The refraction a ray traced through the US76 shells (Snell's invariant,
// Smart's integral) undergoes, against ERFA's model (eraRefco, A tan z + B
// tan^3 z) for the same dry air at the ground: within 1 arcsec at 45 and
// 10 deg apparent altitude (issue 20 item 9). At 5 deg ERFA's two terms
// fall 22" (4 %) short of the ray trace, so the engine's refraction takes
// Bennett's formula there (blended from 10 deg down), within 1 % of it; the
// issue's 1" at 5 deg is beyond ERFA's model itself.
TEST(Refraction, RayTracedUS76AgainstErfa) {
  const auto p = us76();
  const EarthFigure earth;
  const Vec3 site(earth.equatorial_radius_m, 0, 0);
  const Densities ground = p->at(0.0);
  const RefractionConstants c = refraction_constants(ground.pressure_Pa, ground.temperature_K, 0.0, 0.55);
  const auto traced = [&](double h_deg) {
    const double h = h_deg * constants::rad_per_deg;
    return ray_traced_refraction_rad(*p, earth, site, Vec3(std::sin(h), 0, std::cos(h)));
  };
  const auto erfa = [&](double h_deg) {
    const double t = std::tan((90.0 - h_deg) * constants::rad_per_deg);
    return c.a_rad * t + c.b_rad * t * t * t;
  };
  for (const double h_deg : {45.0, 10.0}) {
    EXPECT_NEAR(traced(h_deg) / kArcsec, erfa(h_deg) / kArcsec, 1.0) << h_deg << " deg";
    EXPECT_NEAR(refraction_from_apparent_rad(c, h_deg * constants::rad_per_deg) / kArcsec, erfa(h_deg) / kArcsec, 1e-9);
  }
  EXPECT_NEAR(erfa(5.0) / traced(5.0), 0.96, 0.01);
  for (const double h_deg : {5.0, 3.0, 1.0, 0.0})
    EXPECT_NEAR(refraction_from_apparent_rad(c, h_deg * constants::rad_per_deg) / traced(h_deg), 1.0, 0.03) << h_deg;
  EXPECT_NEAR(refraction_from_apparent_rad(c, 5.0 * constants::rad_per_deg) / traced(5.0), 1.0, 0.01);
  // 45 deg: about 57 arcsec at sea level.
  EXPECT_NEAR(refraction_from_apparent_rad(c, 45 * constants::rad_per_deg) / kArcsec, 57.2, 1.0);
}

// Near the horizon: Bennett's 34.5' at 0 deg (1010 hPa, 10 C); continuous
// across the blend; true and apparent consistent; no refraction in vacuum.
TEST(Refraction, HorizonBlendAndInverse) {
  const RefractionConstants c = refraction_constants(101000.0, 283.0, 0.5, 0.55);
  EXPECT_NEAR(refraction_from_apparent_rad(c, 0.0) / kArcsec / 60.0, 34.5, 0.2);
  double previous = refraction_from_apparent_rad(c, -1.0 * constants::rad_per_deg);
  for (double h = -1.0; h <= 90.0; h += 0.01) {
    const double r = refraction_from_apparent_rad(c, h * constants::rad_per_deg);
    EXPECT_TRUE(std::isfinite(r) && r >= 0);
    EXPECT_LT(std::fabs(r - previous), 0.3 * 0.01 * constants::rad_per_deg) << h;  // no step: dR/dh < 0.3 near the horizon
    previous = r;
  }
  for (const double e_deg : {-0.5, 0.0, 2.0, 4.0, 10.0, 60.0}) {
    const double e = e_deg * constants::rad_per_deg;
    const double r = refraction_from_true_rad(c, e);
    EXPECT_NEAR(refraction_from_apparent_rad(c, e + r), r, 1e-3 * kArcsec) << e_deg;
  }
  EXPECT_EQ(refraction_from_apparent_rad(refraction_constants(0.0, 283.0, 0.5, 0.55), 0.1), 0.0);
}

// The US standard profile's own ground humidity is 46 % (ERRATA on 6.2.5.4).
// The refraction of a point at a finite distance (issue 20 item 6),
// atmosphere::chord_refraction:
// - a target 20 km away on a near-level line from the US76 ground is seen
//   k D / (2 R_E) above its place, with the geodetic coefficient of
//   refraction k = 503 P / T^2 (0.0343 + dT/dh) (P hPa, T K, dT/dh K/m;
//   Brunner and Angus, e.g. Bomford "Geodesy" 4th ed., 3.07) for the US76
//   ground (1013.25 hPa, 288.15 K, -0.0065 K/m): k = 0.171, within 3 %
//   (the air changes over the 175 m the line climbs);
// - a star (1e12 m) shows the ray's whole bending, which equals Smart's
//   integral (ray_traced_refraction_rad, Gauss-Legendre per layer) within
//   0.5 % at 30 and 10 deg (two integrations of one ray: the march is
//   converged to 0.03 %, 1.1" above Smart's at 10 deg; the engine takes
//   only their ratio, chord over bending, from the march);
// - a satellite 1,000 km up at 10 deg shows a little less (the bent ray's
//   parallax), and the share grows with the distance;
// - the chord is continuous across the top of the atmosphere and across
//   the horizon of a site 3 km up.
TEST(Refraction, ChordToPointsAtFiniteDistance) {
  const auto p = us76();
  const EarthFigure earth;
  const double a = earth.equatorial_radius_m;
  const Vec3 site(a, 0, 0);
  const auto along = [](double h_deg) {
    const double h = h_deg * constants::rad_per_deg;
    return Vec3(std::sin(h), 0, std::cos(h));
  };
  {
    const double D = 20e3, k = 503.0 * 1013.25 / (288.15 * 288.15) * (0.0343 - 0.0065);
    const ChordRefraction c = chord_refraction(*p, earth, site, along(0.5), D);
    EXPECT_FALSE(c.ends_on_ground);
    EXPECT_NEAR(c.chord_rad / (k * D / (2.0 * a)), 1.0, 0.03) << c.chord_rad / kArcsec << "\"";
  }
  for (const double h_deg : {30.0, 10.0}) {
    const ChordRefraction star = chord_refraction(*p, earth, site, along(h_deg), 1e12);
    EXPECT_NEAR(star.bending_rad / ray_traced_refraction_rad(*p, earth, site, along(h_deg)), 1.0, 0.005) << h_deg;
    EXPECT_NEAR(star.chord_rad / star.bending_rad, 1.0, 1e-5);
  }
  {
    const ChordRefraction leo = chord_refraction(*p, earth, site, along(10.0), 3.0e6);
    const ChordRefraction geo = chord_refraction(*p, earth, site, along(10.0), 3.8e7);
    EXPECT_GT(leo.chord_rad / leo.bending_rad, 0.95);
    EXPECT_LT(leo.chord_rad / leo.bending_rad, geo.chord_rad / geo.bending_rad);
    EXPECT_LT(geo.chord_rad / geo.bending_rad, 1.0);
  }
  {  // straight up from the ground through the top (100 km up at 60 deg elevation ~ 115 km away)
    const double top = p->top_altitude_m();
    const auto at = [&](double altitude) {
      const double e = 60.0 * constants::rad_per_deg;
      const double R = std::sqrt((a + altitude) * (a + altitude) - a * a * std::cos(e) * std::cos(e)) - a * std::sin(e);
      return chord_refraction(*p, earth, site, along(60.0), R).chord_rad;
    };
    EXPECT_NEAR(at(top - 10.0) / at(top + 10.0), 1.0, 1e-4);
    EXPECT_GT(at(top - 10.0), at(0.5 * top));
  }
  {  // a site 3 km up looking 0.1 deg above and below its level line, 50 km out
    const Vec3 high(a + 3000.0, 0, 0);
    const double up = chord_refraction(*p, earth, high, along(0.1), 50e3).chord_rad;
    const double down = chord_refraction(*p, earth, high, along(-0.1), 50e3).chord_rad;
    EXPECT_GT(up, 0.0);
    EXPECT_NEAR(down / up, 1.0, 0.05);
  }
}

TEST(AerosolOptics, GroundHumidityAndSpectra) {
  const auto p = us76();
  const Densities g = p->at(0.0);
  EXPECT_NEAR(relative_humidity_pct(g.h2o_m3, g.temperature_K), 46.0, 1.5);
  const std::string data = resolve_data_dir("");
  // The tables' own values at their humidities (rural 0 %: 1.60500 at 0.3371
  // um, 0.09152 at 10 um; absorption 0.05930 at 0.55).
  const AerosolSpectra rural0 = AerosolSpectra::load(data, "rural", 0.0);
  EXPECT_NEAR(rural0.at(0.55).extinction_per_550, 1.0, 1e-12);
  EXPECT_NEAR(rural0.at(0.3371).extinction_per_550, 1.60500, 1e-5);
  EXPECT_NEAR(rural0.at(10.0).extinction_per_550, 0.09152, 1e-5);
  EXPECT_NEAR(rural0.at(0.55).single_scatter_albedo, 1.0 - 0.05930, 1e-5);
  // Between the tabulated humidities every value lies between theirs.
  const AerosolSpectra rural70 = AerosolSpectra::load(data, "rural", 70.0), rural46 = AerosolSpectra::load(data, "rural", 46.0);
  for (const double l : {0.3, 1.06, 3.0, 10.0}) {
    const double lo = std::min(rural0.at(l).extinction_per_550, rural70.at(l).extinction_per_550);
    const double hi = std::max(rural0.at(l).extinction_per_550, rural70.at(l).extinction_per_550);
    EXPECT_GE(rural46.at(l).extinction_per_550, lo - 1e-12);
    EXPECT_LE(rural46.at(l).extinction_per_550, hi + 1e-12);
    EXPECT_GT(rural46.at(l).asymmetry, 0.4);
  }
  EXPECT_THROW(AerosolSpectra::load(data, "volcanic", 0.0), Error);
}

}  // namespace
}  // namespace eoir::atmosphere
