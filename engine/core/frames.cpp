#include "core/frames.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <erfa.h>

#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "core/constants.hpp"

namespace eoir::frames {

namespace {

constexpr double kPoleNodesPerDay = 86400.0 / kCelestialPoleGridStep_s;

// ERFA's celestial-to-intermediate matrix at grid node k_in_day of TT day
// `day`, computed once per thread and kept (a bounded table).
const Mat3& c2i_node(double day, std::int64_t k_in_day) {
  thread_local std::unordered_map<std::int64_t, Mat3> nodes;
  const std::int64_t key = static_cast<std::int64_t>(day) * static_cast<std::int64_t>(kPoleNodesPerDay) + k_in_day;
  auto it = nodes.find(key);
  if (it != nodes.end()) return it->second;
  if (nodes.size() > 4096) nodes.clear();
  const JulianDate tt =
      EngineTime::from_tt_days(day, static_cast<double>(k_in_day) / kPoleNodesPerDay).to(TimeScale::tt);
  double r[3][3];
  eraC2i06a(tt.jd1, tt.jd2, r);
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r[i][j];
  return nodes.emplace(key, m).first->second;
}

}  // namespace

Mat3 j2000_to_earth_fixed(const EngineTime& t) {
  const double x = t.fraction() * kPoleNodesPerDay;
  const double k = std::floor(x), u = x - k;
  const Mat3 a = c2i_node(t.days(), static_cast<std::int64_t>(k));  // copies: a lookup may clear the table
  const Mat3 b = c2i_node(t.days(), static_cast<std::int64_t>(k) + 1);
  const Mat3 c2i = (1.0 - u) * a + u * b;
  const JulianDate utc = t.to(TimeScale::utc);  // UT1 ~ UTC (see header)
  const double era = eraEra00(utc.jd1, utc.jd2);
  const double c = std::cos(era), s = std::sin(era);
  Mat3 r3;  // R3(ERA): the intermediate frame to Earth-fixed (no polar motion)
  r3 << c, s, 0, -s, c, 0, 0, 0, 1;
  return r3 * c2i;
}

void earth_fixed_to_j2000(const EngineTime& t, const Vec3& r_ef, const Vec3& v_ef, Vec3& r_j2000, Vec3& v_j2000) {
  const Mat3 m = j2000_to_earth_fixed(t);
  const Vec3 omega(0, 0, earth_rotation_rad_per_s);
  r_j2000 = m.transpose() * r_ef;
  v_j2000 = m.transpose() * (v_ef + omega.cross(r_ef));
}

void j2000_to_earth_fixed(const EngineTime& t, const Vec3& r_j2000, const Vec3& v_j2000, Vec3& r_ef, Vec3& v_ef) {
  const Mat3 m = j2000_to_earth_fixed(t);
  const Vec3 omega(0, 0, earth_rotation_rad_per_s);
  r_ef = m * r_j2000;
  v_ef = m * v_j2000 - omega.cross(r_ef);
}

Vec3 geodetic_to_earth_fixed(double lat_deg, double lon_deg, double height_m) {
  Vec3 r;
  GeographicLib::Geocentric::WGS84().Forward(lat_deg, lon_deg, height_m, r.x(), r.y(), r.z());
  return r;
}

Vec3 earth_fixed_to_geodetic(const Vec3& r_ef) {
  Vec3 g;
  GeographicLib::Geocentric::WGS84().Reverse(r_ef.x(), r_ef.y(), r_ef.z(), g.x(), g.y(), g.z());
  return g;
}

Mat3 horizon_to_earth_fixed(double lat_deg, double lon_deg) {
  constexpr double rad = constants::rad_per_deg;
  const double sf = std::sin(lat_deg * rad), cf = std::cos(lat_deg * rad);
  const double sl = std::sin(lon_deg * rad), cl = std::cos(lon_deg * rad);
  Mat3 m;
  m.col(0) = Vec3(-sl, cl, 0.0);            // east
  m.col(1) = Vec3(-sf * cl, -sf * sl, cf);  // north
  m.col(2) = Vec3(cf * cl, cf * sl, sf);    // up: the geodetic normal
  return m;
}

Mat3 ned_to_earth_fixed(double lat_deg, double lon_deg) {
  const Mat3 enu = horizon_to_earth_fixed(lat_deg, lon_deg);
  Mat3 m;
  m.col(0) = enu.col(1);   // north
  m.col(1) = enu.col(0);   // east
  m.col(2) = -enu.col(2);  // down
  return m;
}

void azimuth_elevation_deg(const Vec3& d, double& azimuth_deg, double& elevation_deg) {
  constexpr double deg = constants::deg_per_rad;
  const double horizontal = std::hypot(d.x(), d.y());
  elevation_deg = std::atan2(d.z(), horizontal) * deg;
  azimuth_deg = horizontal > 0 ? std::atan2(d.x(), d.y()) * deg : 0.0;
  if (azimuth_deg < 0) azimuth_deg += 360.0;
  if (azimuth_deg >= 360.0) azimuth_deg -= 360.0;
}

Horizon horizon_at(const EngineTime& t, const Vec3& position_j2000) {
  const Mat3 m = j2000_to_earth_fixed(t);
  Horizon h;
  h.geodetic = earth_fixed_to_geodetic(m * position_j2000);
  h.near_earth = std::fabs(h.geodetic.z()) <= horizon_max_height_m;
  h.j2000_to_enu = horizon_to_earth_fixed(h.geodetic.x(), h.geodetic.y()).transpose() * m;
  return h;
}

Vec3 direction_enu(double azimuth_deg, double elevation_deg) {
  constexpr double rad = constants::rad_per_deg;
  const double ce = std::cos(elevation_deg * rad), se = std::sin(elevation_deg * rad);
  return Vec3(ce * std::sin(azimuth_deg * rad), ce * std::cos(azimuth_deg * rad), se);
}
}  // namespace eoir::frames
