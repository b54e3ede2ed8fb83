// Spec 6.2.2 (self-radiance: emissivity and effective temperature) and 6.2.3
// (reflected: 6.2.3.1 source radiance, 6.2.3.2 sum of sources, 6.2.3.3
// cosine law, 6.2.3.5 SRF) with scenarios/validation/v_srf_ac.json: Sensor1
// on Aircraft1 looks at the top face of Aircraft3 (a box), lit by Aircraft2
// (a 1 m sphere 1 km away, an eq. 7 Lambertian-sphere source), all on the dark
// side of the Earth, no atmosphere.
//
// Independent reference (eq. 4 with eq. 7, Lambertian target of SRF rho_t,
// BRDF rho_t / pi, a source of emittance eps_s and temperature T_s, radius r
// at distance d from the sampled point, incidence theta):
//   L = rho_t / pi * cos(theta) * eps_s * B_band(T_s) * pi r^2 / d^2
// with B_band the Planck band integral (Simpson, validation_support.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "validation_support.hpp"

namespace v = eoir::validation;
using eoir::test::ScenarioHost;

namespace {

constexpr const char* kScenario = "v_srf_ac.json";
constexpr double kHc = 10000.0, kHalfThick = 1.0, kDSensor = 2000.0, kDSource = 1000.0, kRSource = 1.0;
constexpr double kPhiSensor = -30.0 * v::kDeg, kTheta0 = 0.15 * v::kDeg;
constexpr double kLow = 0.4, kHigh = 2.0;

// The geometry of tools/make_v_srf_ac.py, in the equatorial plane (x, y).
struct Geometry {
  double cx, cy, sx, sy, px, py;
  explicit Geometry() {
    cx = v::kWgs84A_m + kHc;
    cy = 0;
    sx = cx + kDSensor * std::cos(kPhiSensor);
    sy = cy + kDSensor * std::sin(kPhiSensor);
    const double t = kHalfThick / std::cos(kPhiSensor);
    px = cx + t * std::cos(kPhiSensor);
    py = cy + t * std::sin(kPhiSensor);
  }
  void source(double theta, double& x, double& y) const {
    x = px + kDSource * std::cos(theta);
    y = py + kDSource * std::sin(theta);
  }
};

void place(nlohmann::json& doc, const std::string& name, double x, double y) {
  double lon = 0, alt = 0;
  v::equator_geodetic(x, y, lon, alt);
  v::set_fixed_geodetic(v::object_named(doc, name), 0.0, lon, alt);
}

// The scenario with Aircraft2 at incidence theta (Aircraft4 at -0.15 deg).
std::function<void(nlohmann::json&)> with_source_at(double theta) {
  return [theta](nlohmann::json& doc) {
    const Geometry g;
    double x = 0, y = 0;
    place(doc, "Aircraft1", g.sx, g.sy);
    place(doc, "Aircraft3", g.cx, g.cy);
    g.source(theta, x, y);
    place(doc, "Aircraft2", x, y);
    g.source(-kTheta0, x, y);
    place(doc, "Aircraft4", x, y);
  };
}

// The radiance of the sample at the centre of the field (on the top face).
double centre_radiance(ScenarioHost& host) {
  host.render();
  const auto p = host.pick(32, 32);
  EXPECT_TRUE(p.hit);
  EXPECT_EQ(p.object, "Aircraft3");
  return p.effective_radiance;
}

double expected_reflected(double theta, double rho_target, double eps_source, double T_source) {
  const double omega = v::kPi * (kRSource / kDSource) * (kRSource / kDSource);
  return rho_target / v::kPi * std::cos(theta) * eps_source * v::planck_band(kLow, kHigh, T_source) * omega;
}

}  // namespace

// 6.2.3.1: the reflected radiance follows the source's emittance (1 -
// reflectance). The spec's table (4990 K source, 100 % target): 1.000552e-3,
// 6.670758e-4, 5.002879e-4, 3.335000e-4 W cm^-2 sr^-1 at reflectance 0,
// 33.33, 50, 66.67 %. Our ratios must equal the emittances within 1e-6; the
// spec's own ratios equal them within 1e-4 (its emittances are rounded to
// four digits), which the second check reproduces. The absolute value at
// emittance 1 is the closed form above within 0.1 % (200-interval midpoint
// band integral, half-sample pick offset).
TEST(Spec_6_2_3_1, ReflectedRadianceProportionalToSourceEmittance) {
  ScenarioHost host(kScenario, with_source_at(kTheta0));
  const double reflectances[] = {0.0, 0.3333, 0.5, 0.6667};
  const double spec_table[] = {1.000552e-3, 6.670758e-4, 5.002879e-4, 3.335000e-4};
  double L0 = 0;
  for (int i = 0; i < 4; ++i) {
    host.set_number("Aircraft2", "reflectance", reflectances[i]);
    host.at(0);
    const double L = centre_radiance(host);
    if (i == 0) {
      L0 = L;
      const double expected = expected_reflected(kTheta0, 1.0, 1.0, 4990.0);
      EXPECT_NEAR(L, expected, 1e-3 * expected) << "eq. 4 with eq. 7, closed form";
      RecordProperty("radiance_emittance_1", std::to_string(L));
      continue;
    }
    const double ratio = L / L0, emittance = 1.0 - reflectances[i];
    EXPECT_NEAR(ratio, emittance, 1e-6 * emittance) << "reflectance " << reflectances[i];
    EXPECT_NEAR(ratio, spec_table[i] / spec_table[0], 1e-4) << "spec 6.2.3.1 table ratio";
  }
}

// 6.2.3.2: a second identical source doubles the reflected radiance. The two
// sources are mirror images about the face normal at the sampled point
// (incidence +-0.15 deg, 5.2 m apart), so the doubling is exact: within 1e-6.
TEST(Spec_6_2_3_2, TwoIdenticalSourcesDoubleTheRadiance) {
  ScenarioHost host(kScenario, with_source_at(kTheta0));
  host.set_number("Aircraft2", "temperature_K", 6000.0);
  host.set_number("Aircraft2", "reflectance", 0.0);
  host.set_number("Aircraft4", "temperature_K", 0.0);
  host.at(0);
  const double one = centre_radiance(host);
  host.set_number("Aircraft4", "temperature_K", 6000.0);
  host.set_number("Aircraft4", "reflectance", 0.0);
  host.at(0);
  const double two = centre_radiance(host);
  EXPECT_NEAR(two / one, 2.0, 2e-6);
  const double expected = expected_reflected(kTheta0, 1.0, 1.0, 6000.0);
  EXPECT_NEAR(one, expected, 1e-3 * expected);
  RecordProperty("one_source", std::to_string(one));
  RecordProperty("two_sources", std::to_string(two));
}

// 6.2.3.3: the source at a constant 1 km from the sampled point, incidence 0
// to 85 deg (B_Test1_AC, smooth mode): L(theta) / L(0) = cos(theta) within
// 0.5 % (spec), and each L(theta) the closed form within 0.5 %.
TEST(Spec_6_2_3_3, CosineLawFrom0To85Degrees) {
  double L0 = 0;
  for (double deg : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 80.0, 85.0}) {
    ScenarioHost host(kScenario, with_source_at(deg * v::kDeg));
    host.set_number("Aircraft2", "temperature_K", 5000.0);
    host.at(0);
    const double L = centre_radiance(host);
    if (deg == 0.0) L0 = L;
    const double c = std::cos(deg * v::kDeg);
    EXPECT_NEAR(L / L0, c, 5e-3 * c) << "incidence " << deg << " deg";
    const double expected = expected_reflected(deg * v::kDeg, 1.0, 1.0, 5000.0);
    EXPECT_NEAR(L, expected, 5e-3 * expected) << "incidence " << deg << " deg";
    std::printf("incidence %5.1f deg: L = %.6e, L/L0 = %.6f, cos = %.6f\n", deg, L, L / L0, c);
  }
}

// 6.2.3.5: the target's SRF from 0 to 1 (V_SRF_AC, 5000 K source of
// reflectance 0, target at 0 K): the radiance is linear in SRF through the
// origin, L(rho) = rho L(1) within 1e-6, and exactly 0 at rho = 0.
TEST(Spec_6_2_3_5, RadianceLinearInTargetSrf) {
  ScenarioHost host(kScenario, with_source_at(kTheta0));
  host.set_number("Aircraft2", "temperature_K", 5000.0);
  host.set_number("Aircraft3", "reflectance", 1.0);
  host.at(0);
  const double L1 = centre_radiance(host);
  ASSERT_GT(L1, 0.0);
  for (double rho : {0.0, 0.1, 0.25, 0.5, 0.75, 0.9}) {
    host.set_number("Aircraft3", "reflectance", rho);
    host.at(0);
    const double L = centre_radiance(host);
    if (rho == 0.0)
      EXPECT_EQ(L, 0.0);
    else
      EXPECT_NEAR(L / L1, rho, 1e-6 * rho) << "SRF " << rho;
  }
}

// 6.2.2: the target's self-radiance alone (source at 0 K, 0.4-2.0 um with 10
// intervals): the pick's spectral radiance is eps B_lambda(T) (eq. 5) at the
// pick's wavelengths (relative 1e-9: the same law, independent constants),
// and the band radiance in exact band integration is the Planck band
// integral times eps within 1e-6; linear in emissivity (1 - SRF).
TEST(Spec_6_2_2, SelfRadianceIsEmissivityTimesPlanck) {
  ScenarioHost host(kScenario, [](nlohmann::json& doc) {
    with_source_at(kTheta0)(doc);
    auto& p = doc["sensors"][0]["parameters"];
    p["spectral_intervals"] = 10;
    p["band_integration"] = "exact";
  });
  host.set_number("Aircraft2", "temperature_K", 0.0);
  for (double T : {1000.0, 3000.0, 5000.0, 6000.0}) {
    double L_black = 0;
    for (double rho : {0.0, 0.25, 0.5, 0.75}) {
      host.set_number("Aircraft3", "temperature_K", T);
      host.set_number("Aircraft3", "reflectance", rho);
      host.at(0);
      host.render();
      const v::SpectralPick sp = v::spectral_pick(host, 32, 32);
      ASSERT_EQ(sp.pick.object, "Aircraft3");
      ASSERT_EQ(sp.wavelengths_um.size(), 10u);
      for (std::size_t i = 0; i < sp.radiance.size(); ++i) {
        const double expected = (1.0 - rho) * v::planck(sp.wavelengths_um[i], T);
        EXPECT_NEAR(sp.radiance[i], expected, 1e-9 * expected) << T << " K, rho " << rho << ", "
                                                               << sp.wavelengths_um[i] << " um";
      }
      const double band = (1.0 - rho) * v::planck_band(kLow, kHigh, T);
      EXPECT_NEAR(sp.pick.effective_radiance, band, 1e-6 * band) << T << " K, rho " << rho;
      if (rho == 0.0) L_black = sp.pick.effective_radiance;
      else EXPECT_NEAR(sp.pick.effective_radiance / L_black, 1.0 - rho, 1e-9) << T << " K";
    }
  }
  // The spectral grid: interval midpoints of 0.4-2.0 um (spec 5.3, midpoint rule).
  host.render();
  const v::SpectralPick sp = v::spectral_pick(host, 32, 32);
  for (std::size_t i = 0; i < sp.wavelengths_um.size(); ++i)
    EXPECT_NEAR(sp.wavelengths_um[i], kLow + (i + 0.5) * 0.16, 1e-12);
}

// 6.2.5.1, as illumination (spec 4.1.5.3): a source looking larger than the
// fidelity knob area_source_solid_angle_sr lights a surface as the sum over
// its tessellation (eq. 8), a smaller one as a Lambertian sphere (eq. 7).
// Where they meet, moving the knob across the source's solid angle (3.1e-6
// sr here) must not change the reflected radiance by more than 2 %; both
// within 2 % of the closed form. At incidence 0 and 60 deg.
TEST(Spec_6_2_5_1, IlluminationAsAreaOrPointSourceAgree) {
  for (double deg : {0.0, 60.0}) {
    double L[2] = {0, 0};
    const double knob[2] = {1e-3, 1e-7};  // above: eq. 7; below: eq. 8
    for (int k = 0; k < 2; ++k) {
      ScenarioHost host(kScenario, [&](nlohmann::json& doc) {
        with_source_at(deg * v::kDeg)(doc);
        doc["sensors"][0]["parameters"]["area_source_solid_angle_sr"] = knob[k];
      });
      host.set_number("Aircraft2", "temperature_K", 5000.0);
      host.at(0);
      L[k] = centre_radiance(host);
    }
    const double expected = expected_reflected(deg * v::kDeg, 1.0, 1.0, 5000.0);
    std::printf("incidence %.0f deg: point source (eq. 7) %.6e, area source (eq. 8) %.6e, closed form %.6e\n", deg,
                L[0], L[1], expected);
    EXPECT_NEAR(L[1] / L[0], 1.0, 2e-2) << "incidence " << deg << " deg";
    EXPECT_NEAR(L[0] / expected, 1.0, 2e-2);
    EXPECT_NEAR(L[1] / expected, 1.0, 2e-2);
  }
}
