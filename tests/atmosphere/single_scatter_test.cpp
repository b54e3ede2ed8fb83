// Single scatter of sunlight into a line of sight (issue 20 items 4 and 9;
// spec 4.1.5.3 eq. 9's L_scatter, 4.3.1.1): against the closed forms of
// single scatter in a plane-parallel atmosphere (Chandrasekhar 1950; Liou,
// An Introduction to Atmospheric Radiation, 2002, eq. 6.5.5), with the
// optical depth tau of the vertical column and the Rayleigh phase function
// P (depolarisation 0.0279):
//   looking up from the ground at zenith cosine mu_v, Sun at mu_s:
//     L = E P / (4 pi mu_v) exp(-tau / mu_v) [1 - exp(-tau (1/mu_s - 1/mu_v))] / (1/mu_s - 1/mu_v)
//   looking down from space onto a black ground:
//     L = E P / (4 pi) mu_s / (mu_s + mu_v) [1 - exp(-tau (1/mu_s + 1/mu_v))]
// At 0.45 um without aerosol (air alone; ozone adds 2 % of the depth there)
// near the zenith, where the Earth's curvature changes nothing measurable:
// within 1.5 %. The Earth's shadow: no scatter at night. DownWelling, the
// sky's irradiance on the ground, against the same solution integrated over
// the hemisphere (Liou eq. 6.5.5 with the azimuth-averaged Rayleigh phase
// function 3 / (4 (1 + 2 gamma)) ((1 + 3 gamma) + (1 - gamma) (mu^2 mu0^2 +
// (1 - mu^2)(1 - mu0^2) / 2)), by 2000-point quadrature): within 2 %.
#include <gtest/gtest.h>

#include <cmath>

#include "atmosphere/path_optics.hpp"
#include "atmosphere/profile.hpp"
#include "atmosphere/rayleigh.hpp"
#include "atmosphere/single_scatter.hpp"
#include "core/constants.hpp"
#include "core/data_dir.hpp"
#include "scene/downwelling.hpp"

namespace eoir::atmosphere {
namespace {

const EarthFigure kEarth;
const Vec3 kGround(kEarth.equatorial_radius_m, 0, 0);  // the vertical is +x

struct Air {
  std::string data = resolve_data_dir("");
  universe::AtmosphereSettings settings;
  std::shared_ptr<const AtmosphereProfile> profile;
  std::unique_ptr<PathOptics> optics;
  std::unique_ptr<SunlightTable> sunlight;
  double tau = 0;  // of the vertical column, Rayleigh and absorption
  explicit Air(universe::AerosolModel aerosol = universe::AerosolModel::none) {
    settings.model = universe::AtmosphereModel::simple;
    settings.aerosol = aerosol;
    profile = AtmosphereProfile::make(settings, data);
    radiometry::SpectralBand b;
    b.low_um = 0.449;
    b.high_um = 0.451;
    b.intervals = 1;
    optics = std::make_unique<PathOptics>(profile, settings, data, b);
    sunlight = std::make_unique<SunlightTable>(*optics, kEarth);
    const OpticalDepths d = optics->optical_depths(path_to_space(*profile, kEarth, kGround, Vec3::UnitX()));
    tau = d.rayleigh[0] + d.aerosol[0] + d.absorption[0];
  }
  double scatter(const Vec3& start, const PathColumns& path, const Vec3& direction, const Vec3& to_sun) const {
    std::vector<double> L(1, 0.0);
    add_single_scatter(ScatterPath::make(*optics, path), start, direction, to_sun, {1.0}, *sunlight, L);
    return L[0];
  }
};

Vec3 sun_at_zenith_angle(double deg) {
  const double z = deg * constants::pi / 180.0;
  return Vec3(std::cos(z), std::sin(z), 0.0);
}

TEST(SingleScatter, SkyFromTheGroundAgainstPlaneParallel) {
  const Air air;
  for (const double view_deg : {0.0, 20.0}) {
    const double v = view_deg * constants::pi / 180.0;
    const Vec3 d(std::cos(v), -std::sin(v), 0.0);
    const Vec3 s = sun_at_zenith_angle(30.0);
    const double mu_v = d.x(), mu_s = s.x(), k = 1.0 / mu_s - 1.0 / mu_v;
    const double expected = rayleigh_phase(s.dot(d)) / (4.0 * constants::pi * mu_v) * std::exp(-air.tau / mu_v) *
                            (std::fabs(k) > 1e-12 ? (1.0 - std::exp(-air.tau * k)) / k : air.tau);
    const double got = air.scatter(kGround, path_to_space(*air.profile, kEarth, kGround, d), d, s);
    EXPECT_NEAR(got / expected, 1.0, 0.015) << "view zenith " << view_deg << " deg";
  }
}

TEST(SingleScatter, NadirFromSpaceAgainstPlaneParallel) {
  const Air air;
  const Vec3 observer = kGround + Vec3(700e3, 0, 0);
  for (const double sun_deg : {0.0, 30.0, 50.0}) {
    const Vec3 s = sun_at_zenith_angle(sun_deg);
    const Vec3 d = -Vec3::UnitX();
    const double mu_s = s.x(), mu_v = 1.0;
    const double expected = rayleigh_phase(s.dot(d)) / (4.0 * constants::pi) * mu_s / (mu_s + mu_v) *
                            (1.0 - std::exp(-air.tau * (1.0 / mu_s + 1.0 / mu_v)));
    const double got = air.scatter(observer, path_between(*air.profile, kEarth, observer, kGround), d, s);
    EXPECT_NEAR(got / expected, 1.0, 0.015) << "Sun zenith " << sun_deg << " deg";
  }
}

TEST(SingleScatter, NoScatterInTheEarthsShadowAndContinuousAtSunset) {
  const Air air(universe::AerosolModel::rural);
  const PathColumns up = path_to_space(*air.profile, kEarth, kGround, Vec3::UnitX());
  // Sun 30 deg below the horizon: the shadow's edge overhead is ~1000 km up.
  EXPECT_EQ(air.scatter(kGround, up, Vec3::UnitX(), sun_at_zenith_angle(120.0)), 0.0);
  // Through sunset the zenith sky dims smoothly: finite, never negative,
  // never brighter, and in steps of 0.05 deg never by more than 30 % while
  // it is above 1e-4 of its value with the Sun 10 deg up (the shadow's edge
  // climbs ~0.6 km per step, a tenth of the air's scale height).
  const double day = air.scatter(kGround, up, Vec3::UnitX(), sun_at_zenith_angle(80.0));
  double previous = day;
  for (double z = 80.05; z <= 100.0; z += 0.05) {
    const double L = air.scatter(kGround, up, Vec3::UnitX(), sun_at_zenith_angle(z));
    ASSERT_TRUE(std::isfinite(L) && L >= 0.0) << z;
    EXPECT_LE(L, previous * 1.001 + 1e-300) << "the zenith sky brightens as the Sun sets, at " << z;
    if (L > 1e-4 * day) {
      EXPECT_GE(L, previous * 0.7) << "a jump at Sun zenith " << z;
    }
    previous = L;
  }
}

TEST(SingleScatter, DownwellingAgainstPlaneParallel) {
  const Air air;
  const scene::Downwelling down(*air.optics, *air.sunlight, kEarth);
  constexpr double rho = 0.0279, gamma = rho / (2.0 - rho);
  for (const double sun_deg : {0.0, 30.0, 60.0}) {
    const double mu0 = std::cos(sun_deg * constants::pi / 180.0), tau = air.tau;
    double expected = 0;
    const int n = 2000;
    for (int k = 0; k < n; ++k) {  // midpoint rule in mu over (0, 1)
      const double mu = (k + 0.5) / n;
      const double phase = 3.0 / (4.0 * (1.0 + 2.0 * gamma)) *
                           ((1.0 + 3.0 * gamma) + (1.0 - gamma) * (mu * mu * mu0 * mu0 + 0.5 * (1 - mu * mu) * (1 - mu0 * mu0)));
      const double L = std::fabs(mu0 - mu) > 1e-9
                           ? phase / (4.0 * constants::pi) * mu0 / (mu0 - mu) * (std::exp(-tau / mu0) - std::exp(-tau / mu))
                           : phase / (4.0 * constants::pi) * tau / mu0 * std::exp(-tau / mu0);
      expected += 2.0 * constants::pi * mu * L / n;
    }
    std::vector<double> got;
    down.scatter_per_sun(mu0, got);
    EXPECT_NEAR(got[0] / expected, 1.0, 0.02) << "Sun zenith " << sun_deg << " deg: " << got[0] << " vs " << expected;
  }
}

}  // namespace
}  // namespace eoir::atmosphere
