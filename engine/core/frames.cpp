#include "core/frames.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <erfa.h>

namespace eoir::frames {

Mat3 j2000_to_earth_fixed(const EngineTime& t) {
  const JulianDate tt = t.to(TimeScale::tt);
  const JulianDate utc = t.to(TimeScale::utc);  // UT1 ~ UTC (see header)
  double r[3][3];
  eraC2t06a(tt.jd1, tt.jd2, utc.jd1, utc.jd2, 0.0, 0.0, r);
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = r[i][j];
  return m;
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
}  // namespace eoir::frames
