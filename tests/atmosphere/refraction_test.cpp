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
