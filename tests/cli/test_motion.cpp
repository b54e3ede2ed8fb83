// Unit tests of the CLI's host-side motion models (plugin_host/cli/motion.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "iso_time.hpp"
#include "motion.hpp"

using namespace eoir::cli;

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kMu = kMuEarthKm3s2 * 1e9;

KeplerElements elements(double a_km, double e, double i_deg, double raan_deg, double argp_deg, double nu_deg) {
  KeplerElements el;
  el.semi_major_axis_m = a_km * 1e3;
  el.eccentricity = e;
  el.inclination = i_deg * kDeg;
  el.raan = raan_deg * kDeg;
  el.arg_perigee = argp_deg * kDeg;
  el.mean_anomaly_at_epoch = true_to_mean_anomaly(nu_deg * kDeg, e);
  el.epoch_s = parse_iso("2010-08-25T18:00:00Z");
  return el;
}

double distance(const Vec3& a, const Vec3& b) { return norm(sub(a, b)); }
}  // namespace

TEST(Kepler, SolverResidualUpToHighEccentricity) {
  for (double e : {0.0, 0.1, 0.5, 0.7, 0.9, 0.97, 0.99}) {
    for (int k = -720; k <= 720; k += 7) {
      const double m = k * kDeg;
      const double E = solve_kepler(m, e);
      EXPECT_NEAR(E - e * std::sin(E), m, 1e-12) << "e=" << e << " M=" << m;
    }
  }
  EXPECT_THROW(solve_kepler(1.0, 1.0), std::invalid_argument);
}

TEST(Kepler, CircularOrbitReturnsAfterOnePeriod) {
  const KeplerOrbit orbit(elements(7000.0, 0.0, 51.6, 30.0, 0.0, 45.0));
  const double t0 = parse_iso("2010-08-25T18:00:00Z");
  const PosVel a = orbit.at(t0), b = orbit.at(t0 + orbit.period_s());
  EXPECT_LT(distance(a.position, b.position), 1.0);
  EXPECT_LT(distance(a.velocity, b.velocity), 1e-3);
  EXPECT_NEAR(norm(a.position), 7000e3, 1e-3);
  EXPECT_NEAR(orbit.period_s(), 2 * 3.14159265358979323846 * std::sqrt(std::pow(7000e3, 3) / kMu), 1e-6);
  // Circular speed and orthogonality.
  EXPECT_NEAR(norm(a.velocity), std::sqrt(kMu / 7000e3), 1e-6);
  EXPECT_NEAR(dot(a.position, a.velocity), 0.0, 1e-3 * norm(a.position));
}

TEST(Kepler, GeostationaryPeriodIsOneSiderealDay) {
  const KeplerOrbit orbit(elements(42164.17, 0.0, 0.0, 0.0, 0.0, 0.0));
  EXPECT_NEAR(orbit.period_s(), 86164.1, 1.0);
}

TEST(Kepler, EnergyAndMomentumConservedForEccentricOrbit) {
  const KeplerOrbit orbit(elements(26560.0, 0.7, 63.4, 100.0, 270.0, 0.0));
  const double expected = -kMu / (2 * 26560e3);
  const double t0 = parse_iso("2010-08-25T18:00:00Z");
  const PosVel s0 = orbit.at(t0);
  const Vec3 h0 = cross(s0.position, s0.velocity);
  EXPECT_NEAR(norm(s0.position), 26560e3 * 0.3, 1e-3);  // starts at perigee
  for (int k = 0; k <= 200; ++k) {
    const PosVel s = orbit.at(t0 + k * orbit.period_s() / 137.0);
    EXPECT_NEAR(orbital_energy(s, kMu) / expected, 1.0, 1e-11) << "k=" << k;
    EXPECT_LT(distance(cross(s.position, s.velocity), h0) / norm(h0), 1e-11) << "k=" << k;
  }
  // Velocity is the derivative of position.
  // (Times near 3.3e8 s: divide by the representable difference of times.)
  const double t = t0 + 1234.5, ta = t + 0.01, tb = t - 0.01;
  const Vec3 fd = scale(sub(orbit.at(ta).position, orbit.at(tb).position), 1 / (ta - tb));
  EXPECT_LT(distance(fd, orbit.at(t).velocity), 1e-4);
}

TEST(Kepler, RejectsBadElements) {
  EXPECT_THROW(KeplerOrbit(elements(7000.0, 1.2, 0, 0, 0, 0)), std::invalid_argument);
  EXPECT_THROW(KeplerOrbit(elements(-7000.0, 0.0, 0, 0, 0, 0)), std::invalid_argument);
}

TEST(Ephemeris, ExactAtNodesAndRefusedOutside) {
  const KeplerOrbit orbit(elements(7000.0, 0.01, 28.5, 0, 0, 0));
  const double t0 = parse_iso("2010-08-25T18:00:00Z");
  std::vector<EphemerisPoint> pts;
  for (int k = 0; k <= 10; ++k) {
    const PosVel s = orbit.at(t0 + 60.0 * k);
    pts.push_back({t0 + 60.0 * k, s.position, s.velocity});
  }
  const Ephemeris eph(pts);
  for (const auto& p : pts) {
    const PosVel s = eph.at(p.t_s);
    EXPECT_EQ(s.position, p.position);
    EXPECT_EQ(s.velocity, p.velocity);
  }
  // Between nodes the Hermite cubic follows the orbit closely (60 s spacing).
  for (double dt = 7.0; dt < 600.0; dt += 31.0)
    EXPECT_LT(distance(eph.at(t0 + dt).position, orbit.at(t0 + dt).position), 1.0) << dt;
  try {
    eph.at(t0 - 1.0);
    FAIL() << "no exception";
  } catch (const std::out_of_range& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("outside the ephemeris [2010-08-25T18:00:00Z, 2010-08-25T18:10:00Z]"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("2010-08-25T17:59:59Z"), std::string::npos) << msg;
  }
  EXPECT_THROW(eph.at(t0 + 601.0), std::out_of_range);
}

TEST(Ephemeris, LinearMotionIsReproducedExactly) {
  const double t0 = 1000.0;
  std::vector<EphemerisPoint> pts{{t0, {0, 0, 0}, {1, 2, 3}}, {t0 + 10, {10, 20, 30}, {1, 2, 3}}};
  const Ephemeris eph(pts);
  const PosVel s = eph.at(t0 + 2.5);
  EXPECT_NEAR(s.position[0], 2.5, 1e-12);
  EXPECT_NEAR(s.position[2], 7.5, 1e-12);
  EXPECT_NEAR(s.velocity[1], 2.0, 1e-12);
  // Without velocities they are estimated by finite differences.
  std::vector<EphemerisPoint> nov{{t0, {0, 0, 0}, {}}, {t0 + 10, {10, 20, 30}, {}}};
  EXPECT_NEAR(Ephemeris(nov, false).at(t0 + 5).position[1], 10.0, 1e-12);
  EXPECT_THROW(Ephemeris({pts[0]}), std::invalid_argument);
  EXPECT_THROW(Ephemeris({pts[1], pts[0]}), std::invalid_argument);
}

TEST(Attitude, NadirPointsBodyZToEarthCentre) {
  const KeplerOrbit orbit(elements(7000.0, 0.0, 51.6, 30.0, 10.0, 45.0));
  const PosVel s = orbit.at(parse_iso("2010-08-25T18:00:00Z"));
  const Quat q = nadir_attitude(s);
  const Vec3 z = rotate(q, {0, 0, 1}), x = rotate(q, {1, 0, 0});
  const Vec3 down = normalize(scale(s.position, -1));
  EXPECT_LT(distance(z, down), 1e-12);
  EXPECT_LT(distance(x, normalize(s.velocity)), 1e-12);  // circular: v is perpendicular
  EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-14);
}

TEST(Attitude, PointZAxisHandlesParallelHint) {
  const Quat q = point_z_axis({0, 0, 5}, {0, 0, 1});
  EXPECT_LT(distance(rotate(q, {0, 0, 1}), {0, 0, 1}), 1e-12);
  const Quat r = point_z_axis({1, 1, 0}, {0, 0, 1});
  EXPECT_LT(distance(rotate(r, {0, 0, 1}), normalize(Vec3{1, 1, 0})), 1e-12);
  EXPECT_LT(distance(rotate(r, {1, 0, 0}), {0, 0, 1}), 1e-12);
}

TEST(IsoTime, RoundTripAndErrors) {
  EXPECT_EQ(parse_iso("2000-01-01T12:00:00Z"), 0.0);
  EXPECT_EQ(format_iso(parse_iso("2010-08-25T18:05:00Z")), "2010-08-25T18:05:00Z");
  EXPECT_EQ(format_iso(parse_iso("2024-02-29T23:59:59.250Z")), "2024-02-29T23:59:59.250Z");
  EXPECT_EQ(parse_iso("2010-08-26") - parse_iso("2010-08-25T00:00:00Z"), 86400.0);
  EXPECT_THROW(parse_iso("2010-02-30T00:00:00Z"), std::invalid_argument);
  EXPECT_THROW(parse_iso("yesterday"), std::invalid_argument);
  EXPECT_THROW(parse_iso("2010-08-25T18:00:00+02:00"), std::invalid_argument);
}

// ------------------------------------------------------------ ballistic
namespace {
// Height above the WGS84 ellipsoid along the geocentric direction.
double height_along_radius(const Vec3& p) {
  constexpr double a = 6378137.0, b = 6356752.314245;
  const Vec3 u = normalize(p);
  return norm(p) - 1.0 / std::sqrt((u[0] * u[0] + u[1] * u[1]) / (a * a) + u[2] * u[2] / (b * b));
}
}  // namespace

// The arc starts and ends on the geodetic surface points, at rest before the
// launch and after the impact.
TEST(Ballistic, EndsOnTheLaunchAndImpactPoints) {
  const double t0 = parse_iso("2010-08-25T02:00:10Z");
  const BallisticArc arc(5.0, -30.0, 30.0, -15.0, t0, 170.0, std::nan(""));
  EXPECT_LT(distance(arc.at(t0 - 5).position, geodetic_to_ecef(5.0, -30.0, 0.0)), 1e-3);
  EXPECT_LT(distance(arc.at(t0).position, geodetic_to_ecef(5.0, -30.0, 0.0)), 1e-3);
  EXPECT_EQ(norm(arc.at(t0 - 5).velocity), 0.0);
  EXPECT_EQ(norm(arc.at(t0).velocity), 0.0);  // the powered flight starts from rest
  EXPECT_LT(distance(arc.at(arc.impact_s()).position, geodetic_to_ecef(30.0, -15.0, 0.0)), 1e-3);
  EXPECT_LT(distance(arc.at(arc.impact_s() + 100).position, geodetic_to_ecef(30.0, -15.0, 0.0)), 1e-3);
  EXPECT_EQ(norm(arc.at(arc.impact_s() + 100).velocity), 0.0);
  EXPECT_NEAR(arc.impact_s() - t0, 85.0 + arc.free_flight_s(), 1e-6);  // (t0 ~ 1e9 s)
}

// The minimum-energy ellipse between two points of one radius leaves at the
// flight-path angle (pi - theta) / 4 above the local horizontal (Bate,
// Mueller and White 1971, section 6.2) with the speed of vis-viva for a =
// (R + R sin(theta/2)) / 2 (its semi-major axis: a half of r + c over 2, c
// the chord); the speed rises from rest over the burn to the arc's speed,
// continuous at burnout.
TEST(Ballistic, MinimumEnergyFlightPathAngleAndSpeed) {
  const double t0 = 1000.0;
  const BallisticArc coast(0.0, 0.0, 0.0, 40.0, t0, 0.0, std::nan(""));  // along the equator: theta = 40 deg
  const PosVel s = coast.at(t0);
  const double theta = 40.0 * kDeg, R = kBallisticEarthRadius_m;
  const double gamma = std::asin(dot(normalize(s.velocity), normalize(s.position)));
  EXPECT_NEAR(gamma, (3.14159265358979323846 - theta) / 4, 1e-9);
  const double a = (R + R * std::sin(theta / 2)) / 2;
  EXPECT_NEAR(norm(s.velocity), std::sqrt(kMu * (2 / R - 1 / a)), 1e-6);
  // Apogee midway in time, its radius a (1 + e) with the apogee's speed.
  const PosVel mid = coast.at(t0 + coast.free_flight_s() / 2);
  EXPECT_NEAR(dot(mid.velocity, normalize(mid.position)), 0.0, 1e-6);
  EXPECT_NEAR(height_along_radius(mid.position), coast.apogee_radius_m() - R, 1e-3);
  const BallisticArc boost(0.0, 0.0, 0.0, 40.0, t0, 120.0, std::nan(""));
  EXPECT_NEAR(norm(boost.at(t0 + 60).velocity), 0.5 * norm(coast.at(t0 + 15).velocity), 1e-6);  // tau = 60^2/240
  EXPECT_NEAR(norm(boost.at(t0 + 120 - 1e-6).velocity), norm(boost.at(t0 + 120 + 1e-6).velocity), 1e-3);
}

// A given apogee: reached midway, that high above the ellipsoid.
TEST(Ballistic, GivenApogee) {
  for (double apogee_m : {300e3, 1500e3}) {
    const BallisticArc arc(40.0, 10.0, 35.0, 40.0, 0.0, 60.0, apogee_m);
    const double mid = 30.0 + arc.free_flight_s() / 2;
    EXPECT_NEAR(height_along_radius(arc.at(mid).position), apogee_m, 1e-3) << apogee_m;
    EXPECT_LT(distance(arc.at(arc.impact_s()).position, geodetic_to_ecef(35.0, 40.0, 0.0)), 1e-3);
  }
}

TEST(Ballistic, BadInputNamesTheValue) {
  auto why = [](double lat2, double lon2, double burn, double apogee) {
    try {
      BallisticArc(0.0, 0.0, lat2, lon2, 0.0, burn, apogee);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(why(0.0, 0.001, 10, std::nan("")).find("impact"), std::string::npos);   // 111 m away
  EXPECT_NE(why(0.0, 180.0, 10, std::nan("")).find("impact"), std::string::npos);   // antipodal
  EXPECT_NE(why(10.0, 10.0, -1, std::nan("")).find("burn_s"), std::string::npos);
  EXPECT_NE(why(10.0, 10.0, 1e6, std::nan("")).find("burn_s"), std::string::npos);
  EXPECT_NE(why(10.0, 10.0, 10, 10.0).find("apogee_height_m"), std::string::npos);
  EXPECT_NE(why(std::nan(""), 10.0, 10, std::nan("")).find("finite"), std::string::npos);
}
