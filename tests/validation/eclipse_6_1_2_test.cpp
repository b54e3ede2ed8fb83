// Spec 6.1.2 (V_Test2, distance ordering and obscuration, with its penumbra
// part) at the scenario level: the unit test tests/geometry/eclipse_test.cpp
// checks geometry::solar_disk_visible_fraction alone; this one runs the whole
// engine -- host-pushed Kepler states, the world's occulters, the thermal
// model, a rendered frame and a pick -- on scenarios/validation/v_test2.json.
//
// Satellite2 (GEO, circular, equatorial) crosses the Earth's shadow at the
// 2010 spring equinox. Its thermal model "eclipse" gives T^4 = f T_sun^4 with
// f the visible fraction of the solar disc (eclipse temperature 0 K), so the
// temperature of a pick on Satellite2 measures f: 1 before first contact, 0
// between second and third contact. The four contacts are found by
// bisection in time and converted to true anomaly, nu = nu0 + n t.
//
// Independent reference: the classic conical shadow of a spherical Earth of
// radius a = 6378.137 km (at the equinox the Sun and the orbit lie in the
// equator, where the WGS84 silhouette reaches exactly a): with the Sun's
// apparent radius rho_s = asin(R_sun / |s - p|), the Earth's rho_e =
// asin(a / |p|) and theta the angle between them seen from the satellite,
// first/fourth contact at theta = rho_e + rho_s, second/third at theta =
// rho_e - rho_s. The Sun from ERFA's eraEpv00, R_sun = 695,700 km (IAU 2015).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>

#include "validation_support.hpp"

namespace v = eoir::validation;
using eoir::test::ScenarioHost;

namespace {

constexpr const char* kScenario = "v_test2.json";
constexpr const char* kEpoch = "2010-03-20T17:32:00Z";
constexpr double kGeo = 42164.2e3, kMu = 3.986004418e14, kSunRadius = 695700e3;
constexpr double kTsun = 300.0;
// Fully lit: f = (T / 300 K)^4 is 1 up to the rounding of T = (f 300^4)^(1/4);
// near a contact the hidden fraction grows as (angle past contact)^(3/2), so
// 1e-9 moves the contacts by milliseconds.
constexpr double kLit = 1.0 - 1e-9;

double initial_true_anomaly_deg() {
  std::ifstream in(eoir::test::validation_scenario(kScenario));
  nlohmann::json doc = nlohmann::json::parse(in);
  return v::object_named(doc, "Satellite2")["motion"]["true_anomaly_deg"].get<double>();
}

double mean_motion() { return std::sqrt(kMu / (kGeo * kGeo * kGeo)); }

// The conical-shadow angles at t seconds after the epoch: theta - rho_e and rho_s.
void cone(double nu0_rad, double t, double& theta_minus_rho_e, double& rho_s) {
  const double nu = nu0_rad + mean_motion() * t;
  const v::V3 p{kGeo * std::cos(nu), kGeo * std::sin(nu), 0.0};
  const v::V3 s = v::sun_geocentric_m(kEpoch, t);
  const v::V3 to_sun = s - p, to_earth = -1.0 * p;
  const double theta = std::acos(v::dot(to_sun, to_earth) / (v::norm(to_sun) * v::norm(to_earth)));
  rho_s = std::asin(kSunRadius / v::norm(to_sun));
  theta_minus_rho_e = theta - std::asin(v::kWgs84A_m / v::norm(p));
}

// Bisection of a predicate false at lo and true at hi, to 1 ms.
double boundary(const std::function<bool(double)>& pred, double lo, double hi) {
  EXPECT_FALSE(pred(lo)) << lo;
  EXPECT_TRUE(pred(hi)) << hi;
  while (hi - lo > 1e-3) {
    const double mid = 0.5 * (lo + hi);
    (pred(mid) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(Spec_6_1_2, GeoSatelliteThroughTheEarthsShadow) {
  ScenarioHost host(kScenario);
  const double nu0 = initial_true_anomaly_deg() * v::kDeg;
  // f from the engine: the temperature of the pick at the centre of Sensor1's
  // field, which Satellite2 fills.
  int renders = 0;
  auto fraction = [&](double t) {
    host.at(t);
    host.render();
    ++renders;
    const v::SpectralPick sp = v::spectral_pick(host, 16, 16);
    EXPECT_EQ(sp.pick.object, "Satellite2") << t;
    return std::pow(sp.temperature_K / kTsun, 4.0);
  };
  // Coarse scan (20 s steps over 2 h) for the brackets, then bisection.
  double first = -1, second = -1, third = -1, fourth = -1;
  double prev_t = 0;
  ASSERT_GE(fraction(0), kLit) << "Satellite2 must start in sunlight";
  for (double t = 20; t <= 7200 && fourth < 0; t += 20) {
    const double f = fraction(t);
    if (first < 0 && f < kLit) first = boundary([&](double x) { return fraction(x) < kLit; }, prev_t, t);
    if (second < 0 && f == 0.0) second = boundary([&](double x) { return fraction(x) == 0.0; }, prev_t, t);
    if (second >= 0 && third < 0 && f > 0.0) third = boundary([&](double x) { return fraction(x) > 0.0; }, prev_t, t);
    if (third >= 0 && fourth < 0 && f >= kLit)
      fourth = boundary([&](double x) { return fraction(x) >= kLit; }, prev_t, t);
    prev_t = t;
  }
  ASSERT_GT(fourth, 0) << "Satellite2 did not leave the shadow within 2 h";
  // In the penumbra f falls monotonically from 1 to 0 (sampled at 8 points).
  double last = 1.0;
  for (int i = 1; i < 8; ++i) {
    const double f = fraction(first + (second - first) * i / 8.0);
    EXPECT_LT(f, last);
    EXPECT_GT(f, 0.0);
    last = f;
  }

  // The conical shadow, independently.
  const auto outer = [&](double t) {
    double d = 0, rs = 0;
    cone(nu0, t, d, rs);
    return d < rs;  // theta < rho_e + rho_s: some of the disc hidden
  };
  const auto inner = [&](double t) {
    double d = 0, rs = 0;
    cone(nu0, t, d, rs);
    return d < -rs;  // theta < rho_e - rho_s: all hidden
  };
  const double c1 = boundary(outer, first - 60, first + 60);
  const double c2 = boundary(inner, second - 60, second + 60);
  const double c3 = boundary([&](double t) { return !inner(t); }, third - 60, third + 60);
  const double c4 = boundary([&](double t) { return !outer(t); }, fourth - 60, fourth + 60);

  const double n_deg = mean_motion() / v::kDeg;
  const auto nu_deg = [&](double t) { return std::fmod(nu0 / v::kDeg + n_deg * t + 720.0, 360.0); };
  const double engine[4] = {first, second, third, fourth}, conical[4] = {c1, c2, c3, c4};
  const char* names[4] = {"first contact (penumbra entry)", "second contact (umbra entry)",
                          "third contact (umbra exit)", "fourth contact (penumbra exit)"};
  for (int i = 0; i < 4; ++i) {
    std::printf("%-32s t = %8.3f s nu = %.5f deg; conical t = %8.3f s nu = %.5f deg\n", names[i], engine[i],
                nu_deg(engine[i]), conical[i], nu_deg(conical[i]));
    EXPECT_NEAR(n_deg * engine[i], n_deg * conical[i], 0.01) << names[i] << ": true anomalies within 0.01 deg";
  }
  // Spec 6.1.2 penumbra: sunset and sunrise last the Sun's traverse,
  // 0.5316 deg / 0.004166667 deg/s = 127.58 s, within 3 s.
  std::printf("sunset %.2f s, sunrise %.2f s, umbra %.4f deg of true anomaly; %d renders\n", second - first,
              fourth - third, n_deg * (third - second), renders);
  EXPECT_NEAR(second - first, 127.6, 3.0);
  EXPECT_NEAR(fourth - third, 127.6, 3.0);
  RecordProperty("sunset_s", std::to_string(second - first));
}
