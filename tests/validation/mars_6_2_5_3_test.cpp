// Spec 6.2.5.3 (V_Mars2): Mars at its mean opposition distance (27 Nov 1990)
// as a point source, seen from a GEO satellite (scenarios/validation/
// v_mars2.json). The spectral irradiance at the aperture
// (eoir_target_spectrum_get) must show the reflected peak near 0.6 um and the
// thermal peak near 14 um within 15 % of the spec's 1.698e-11 and 9.85e-13
// W cm^-2 um^-1 (ERRATA: consistent with V = -2.0 at mean opposition).
//
// The spec's values are those of STK EOIR's own Mars (its spectral
// reflectance and 210 K), not of the Applied Optics paper, so they are the
// right yardstick for ours: material mars_surface (JSC Mars-1, SRF 0.152 at
// 0.6 um, emissivity 1 - SRF = 0.95 at 14 um) and 210 K. Where we differ, it
// is by that albedo (their Mars reflectance is not published) and by the
// emissivity: a black body at 210 K would give 9.9e-13 at 14.1 um.
//
// A tighter, independent check: the whole spectrum against eq. 7 for a
// sphere of Mars' volumetric radius, computed here from the published data
// (E-490 table, the material file's SRF, Planck) and ERFA's ephemerides
// (eraPlan94 Mars, eraEpv00 Earth and Sun), within 1 %; eq. 7's phase law is
// Mars' observed one (Mallama & Hilton 2018 eq. 6 as
// tests/sky/planet_magnitudes.hpp transcribes it; issue 21) in place of the
// Lambertian sphere's, with Mars' rotational and orbital corrections
// (-0.066 mag on this date: the table of data/planets/
// mars_brightness_corrections.csv through the test's own interpolation and
// IAU orientation, tests/sky/planet_magnitudes.hpp).
#include <erfa.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "../sky/planet_magnitudes.hpp"
#include "validation_support.hpp"

namespace v = eoir::validation;
using eoir::test::ScenarioHost;

namespace {

constexpr const char* kScenario = "v_mars2.json";
constexpr const char* kEpoch = "1990-11-27T00:00:00Z";

// Mars' SRF from the material file of the data folder (as published there).
v::Table mars_srf() {
  std::ifstream in(std::string(EOIR_DATA_DIR) + "/materials/mars_surface.json");
  if (!in) throw std::runtime_error("mars_surface.json not found in " EOIR_DATA_DIR);
  const nlohmann::json doc = nlohmann::json::parse(in);
  return v::Table{doc["wavelength_um"].get<std::vector<double>>(), doc["reflectance"].get<std::vector<double>>()};
}

double mean_over(const v::Table& t, double a, double b) { return v::integrate_linear(t, a, b) / (b - a); }

// The value of the spectrum at `um` (linear between the samples around it).
double at(const std::vector<double>& wl, const std::vector<double>& E, double um) {
  for (std::size_t i = 0; i + 1 < wl.size(); ++i)
    if (wl[i] <= um && um <= wl[i + 1]) return E[i] + (E[i + 1] - E[i]) * (um - wl[i]) / (wl[i + 1] - wl[i]);
  throw std::runtime_error("wavelength outside the spectrum");
}

}  // namespace

TEST(Spec_6_2_5_3, MarsAsPointSourceReflectedAndThermalPeaks) {
  ScenarioHost host(kScenario);
  ASSERT_EQ(host.target_metric("Target Is Point Source", "Mars"), 1.0);
  std::vector<double> wl, E;
  v::target_spectrum(host, "Mars", wl, E);
  ASSERT_EQ(wl.size(), 2770u);

  // ---- the spec's numbers, 15 %
  const double reflected_06 = at(wl, E, 0.6), thermal_141 = at(wl, E, 14.1);
  std::size_t peak_r = 0, peak_t = 0;
  for (std::size_t i = 0; i < wl.size(); ++i) {
    if (wl[i] < 3.0 && E[i] > E[peak_r]) peak_r = i;
    if (wl[i] > 8.0 && (peak_t == 0 || E[i] > E[peak_t])) peak_t = i;
  }
  std::printf("Mars: E(0.6 um) = %.4e (spec 1.698e-11), E(14.1 um) = %.4e (spec 9.85e-13) W cm^-2 um^-1\n",
              reflected_06, thermal_141);
  std::printf("      reflected peak %.4e at %.3f um, thermal peak %.4e at %.3f um\n", E[peak_r], wl[peak_r],
              E[peak_t], wl[peak_t]);
  EXPECT_NEAR(reflected_06, 1.698e-11, 0.15 * 1.698e-11);
  EXPECT_NEAR(thermal_141, 9.85e-13, 0.15 * 9.85e-13);
  // The thermal peak of eps B(210 K) is at 13.8 um for a black body (Wien);
  // Mars' emissivity barely moves it: 12-16 um.
  EXPECT_GT(wl[peak_t], 12.0);
  EXPECT_LT(wl[peak_t], 16.0);
  EXPECT_NEAR(E[peak_t], 9.85e-13, 0.15 * 9.85e-13);
  // The reflected peak is redder than the Sun's (0.45 um): Mars' SRF rises
  // steeply to 1 um (spec step 4: "further in the red than the paper").
  EXPECT_GT(wl[peak_r], 0.55);
  EXPECT_LT(wl[peak_r], 1.0);

  // ---- eq. 7 independently, every interval within 1 %
  double tt1 = 0, tt2 = 0;
  v::tt_jd(kEpoch, 0.0, tt1, tt2);
  double pvh[2][3], pvb[2][3], mars_h[2][3];
  eraEpv00(tt1, tt2, pvh, pvb);
  ASSERT_EQ(eraPlan94(tt1, tt2, 4, mars_h), 0);
  std::ifstream in(eoir::test::validation_scenario(kScenario));
  const nlohmann::json doc = nlohmann::json::parse(in);
  const double nu = doc["objects"][0]["motion"]["true_anomaly_deg"].get<double>() * v::kDeg;
  const v::V3 earth_h{pvh[0][0] * v::kAu_m, pvh[0][1] * v::kAu_m, pvh[0][2] * v::kAu_m};
  const v::V3 mars{mars_h[0][0] * v::kAu_m - earth_h[0], mars_h[0][1] * v::kAu_m - earth_h[1],
                   mars_h[0][2] * v::kAu_m - earth_h[2]};  // geocentric
  const v::V3 sun = -1.0 * earth_h;
  const v::V3 observer{42164.2e3 * std::cos(nu), 42164.2e3 * std::sin(nu), 0.0};
  const v::V3 to_sun = sun - mars, to_obs = observer - mars;
  const double d_sun = v::norm(to_sun), r = v::norm(to_obs);
  const double psi = std::acos(v::dot(to_sun, to_obs) / (d_sun * r));
  // Mars' rotational and orbital corrections (issue 21), from the face seen
  // (IAU orientation a light time before the epoch) and Mars' heliocentric
  // ecliptic longitude.
  namespace o = eoir::test_oracle;
  const o::MarsCorrectionTables tables = o::read_mars_corrections(EOIR_MARS_CORRECTIONS_CSV);
  const double d_at_mars = (tt1 - 2451545.0) + tt2 - v::norm(observer - mars) / 299792458.0 / 86400.0;
  const v::V3 obs_unit = v::unit(observer - mars), sun_unit = v::unit(sun - mars);
  const double u_obs[3] = {obs_unit[0], obs_unit[1], obs_unit[2]}, u_sun[3] = {sun_unit[0], sun_unit[1], sun_unit[2]};
  const double eps = 84381.406 / 3600.0 * v::kDeg;
  const double helio_lon = std::atan2(mars_h[0][1] * std::cos(eps) + mars_h[0][2] * std::sin(eps), mars_h[0][0]) / v::kDeg;
  const double correction = o::mars_corrections_mag(tables, o::mars_west_longitude_deg(u_obs, d_at_mars),
                                                    o::mars_west_longitude_deg(u_sun, d_at_mars), helio_lon);
  const double phase = std::pow(10.0, -0.4 * (o::mars_v_mag(1.0, 1.0, psi / v::kDeg) - o::mars_v_mag(1.0, 1.0, 0.0) +
                                              correction));
  std::printf("      Mars' rotational and orbital corrections %+.4f mag\n", correction);
  const double R = std::cbrt(3396.19e3 * 3396.19e3 * 3376.20e3);  // volumetric radius (IAU 2015)
  const double omega = v::kPi * R * R / (r * r);
  std::printf("      distance %.6f au, Sun-Mars %.6f au, phase angle %.3f deg, Phase %.6f\n", r / v::kAu_m,
              d_sun / v::kAu_m, psi / v::kDeg, phase);
  const v::Table e490 = v::read_e490(EOIR_E490_FILE), srf = mars_srf();
  const double h = (28.0 - 0.3) / 2770, au2 = (v::kAu_m / d_sun) * (v::kAu_m / d_sun);
  int worse = 0;
  for (std::size_t i = 0; i < wl.size(); ++i) {
    const double a = 0.3 + i * h, b = a + h;
    const double E_sun = mean_over(e490, a, b) * 1e-4 * au2;  // W cm^-2 um^-1 at Mars
    const double rho = mean_over(srf, a, b);
    const double expected = (E_sun * rho * 2.0 / (3.0 * v::kPi) * phase + (1.0 - rho) * v::planck(wl[i], 210.0)) * omega;
    if (std::fabs(E[i] - expected) > 1e-2 * expected && ++worse <= 5)
      ADD_FAILURE() << wl[i] << " um: engine " << E[i] << ", eq. 7 " << expected;
  }
  EXPECT_EQ(worse, 0) << "intervals off eq. 7 by more than 1 %";
}
