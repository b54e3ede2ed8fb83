// The planets' places (issue 21 item 5; universe/vsop87.hpp, the complete
// VSOP87B series from kstars-data): the geocentric astrometric places of
// Mercury..Neptune at four dates 1969-2012 against JPL's DE405 as NOVAS 3.1
// gives them (tests/data/de405_geocentric_planet_places.csv), within 2"; the
// geometric distances within 2" times the distance (the same angle seen
// along the line of sight). ERFA's eraPlan94, which the engine used before,
// is 20" off Mars and Jupiter at some of these dates (printed for the record).
#include <erfa.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/csv_rows.hpp"
#include "core/error.hpp"

#include "universe/central_bodies.hpp"
#include "universe/vsop87.hpp"

namespace u = eoir::universe;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kArcsec = kPi / (180.0 * 3600.0);
constexpr double kAu_m = 149597870700.0;
constexpr double kC_m_s = 299792458.0;

struct Row {
  std::string planet;
  double jd_tt = 0, distance_au = 0, ra_hours = 0, dec_deg = 0;
};

std::vector<Row> rows() {
  std::vector<Row> out;
  for (const std::vector<std::string>& cells : eoir_test::csv_rows(EOIR_DE405_PLANET_PLACES)) {
    Row r;
    r.planet = cells.at(0);
    r.jd_tt = std::stod(cells.at(1));
    r.distance_au = std::stod(cells.at(2));
    r.ra_hours = std::stod(cells.at(3));
    r.dec_deg = std::stod(cells.at(4));
    out.push_back(r);
  }
  return out;
}

eoir::EngineTime tt(double jd) {  // whole TT days since J2000.0 (JD 2451545.0) and the fraction
  const double whole = std::floor(jd - 2451545.0);
  return eoir::EngineTime::from_tt_days(whole, (jd - 2451545.0) - whole);
}

Eigen::Vector3d geocentric(const u::CentralBodyInfo& body, const eoir::EngineTime& t) {
  Eigen::Vector3d r, v;
  u::central_body_state_j2000(body, t, r, v);
  return r;
}

}  // namespace

TEST(PlanetEphemeris, AstrometricPlacesWithinTwoArcsecondsOfDe405) {
  ASSERT_TRUE(u::vsop87::available()) << "built without kstars-data";
  const u::CentralBodyInfo& sun = u::central_body_info(u::CentralBody::sun);
  const auto table = rows();
  ASSERT_EQ(table.size(), 28u);
  for (const Row& row : table) {
    const u::CentralBodyInfo* body = u::find_central_body(row.planet);
    ASSERT_NE(body, nullptr) << row.planet;
    const eoir::EngineTime t = tt(row.jd_tt);
    // Light time: the planet where it was tau ago, seen from the Earth now
    // (heliocentric planet at t - tau minus the Earth at t; the Sun's own
    // barycentric motion over tau moves it by < 0.002").
    const Eigen::Vector3d sun_now = geocentric(sun, t);
    Eigen::Vector3d p = geocentric(*body, t);
    for (int i = 0; i < 4; ++i) {
      const eoir::EngineTime earlier = t.plus_seconds(-p.norm() / kC_m_s);
      p = geocentric(*body, earlier) - geocentric(sun, earlier) + sun_now;
    }
    const Eigen::Vector3d expected(std::cos(row.dec_deg * kPi / 180) * std::cos(row.ra_hours * kPi / 12),
                                   std::cos(row.dec_deg * kPi / 180) * std::sin(row.ra_hours * kPi / 12),
                                   std::sin(row.dec_deg * kPi / 180));
    const double error_arcsec = std::atan2(p.normalized().cross(expected).norm(), p.normalized().dot(expected)) / kArcsec;
    const double distance_au = geocentric(*body, t).norm() / kAu_m;
    const double distance_error_arcsec = std::fabs(distance_au - row.distance_au) / row.distance_au / kArcsec;
    // ERFA's eraPlan94 at the same instant, light time alike (for the record).
    const eoir::JulianDate tdb = t.to(eoir::TimeScale::tdb);
    double plan94_error_arcsec = 0;
    {
      double pv[2][3], eh[2][3], eb[2][3];
      eraEpv00(tdb.jd1, tdb.jd2, eh, eb);
      Eigen::Vector3d q(0, 0, 0);
      for (int i = 0; i < 4; ++i) {
        const double tau_days = q.norm() * kAu_m / kC_m_s / 86400.0;
        eraPlan94(tdb.jd1, tdb.jd2 - tau_days, body->erfa_planet, pv);
        q = Eigen::Vector3d(pv[0][0] - eh[0][0], pv[0][1] - eh[0][1], pv[0][2] - eh[0][2]);
      }
      plan94_error_arcsec = std::atan2(q.normalized().cross(expected).norm(), q.normalized().dot(expected)) / kArcsec;
    }
    std::printf("%-8s JD(TT) %.4f  VSOP87B %.3f\"  distance %.3f\"  (eraPlan94 %.2f\")\n", row.planet.c_str(),
                row.jd_tt, error_arcsec, distance_error_arcsec, plan94_error_arcsec);
    EXPECT_LT(error_arcsec, 2.0) << row.planet << " " << row.jd_tt;
    EXPECT_LT(distance_error_arcsec, 2.0) << row.planet << " " << row.jd_tt;
  }
}

TEST(PlanetEphemeris, BadPlanetNumberIsRefused) {
  double r[3], v[3];
  EXPECT_THROW(u::vsop87::heliocentric_state(0, 2451545.0, 0.0, r, v), eoir::Error);
  EXPECT_THROW(u::vsop87::heliocentric_state(9, 2451545.0, 0.0, r, v), eoir::Error);
}

// The velocity is the derivative of the position (the series differentiated
// term by term): central difference over +-1 h within 1e-6 relative.
TEST(PlanetEphemeris, VelocityIsTheDerivativeOfPosition) {
  for (int planet = 1; planet <= 8; ++planet) {
    double r0[3], v0[3], rm[3], rp[3], v[3];
    u::vsop87::heliocentric_state(planet, 2460000.5, 0.0, r0, v0);
    u::vsop87::heliocentric_state(planet, 2460000.5, -1.0 / 24, rm, v);
    u::vsop87::heliocentric_state(planet, 2460000.5, 1.0 / 24, rp, v);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR((rp[k] - rm[k]) * 12.0, v0[k], 1e-6 * Eigen::Vector3d(v0[0], v0[1], v0[2]).norm()) << planet;
  }
}
