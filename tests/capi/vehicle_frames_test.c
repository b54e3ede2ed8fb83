/* C ABI: EOIR_FRAME_GEODETIC_NED (issue 22 item 3; spec 4.3.4-4.3.5), an
 * aircraft placed by latitude, longitude, height and heading/pitch/roll.
 * Expected values in closed form here: the local north, east and down unit
 * vectors of the WGS84 normal at (lat, lon); the body axes of the ZYX Euler
 * angles (nose = cos h cos p N + sin h cos p E - sin p D; right wing =
 * (cos h sin p sin r - sin h cos r) N + (sin h sin p sin r + cos h cos r) E +
 * cos p sin r D); the Earth-fixed straight line of constant-velocity
 * extrapolation. Bad input names the field. */
#include "check.h"

static const double kRad = 3.14159265358979323846 / 180.0;

/* Body -> NED quaternion {w, x, y, z} of heading, pitch, roll (deg): Rz Ry Rx. */
static void hpr_quaternion(double h, double p, double r, double q[4]) {
  const double ch = cos(0.5 * h * kRad), sh = sin(0.5 * h * kRad);
  const double cp = cos(0.5 * p * kRad), sp = sin(0.5 * p * kRad);
  const double cr = cos(0.5 * r * kRad), sr = sin(0.5 * r * kRad);
  q[0] = ch * cp * cr + sh * sp * sr;
  q[1] = ch * cp * sr - sh * sp * cr;
  q[2] = ch * sp * cr + sh * cp * sr;
  q[3] = sh * cp * cr - ch * sp * sr;
}

/* v_frame = q v q* */
static void rotate(const double q[4], const double v[3], double out[3]) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  int i;
  for (i = 0; i < 3; ++i) out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
}

/* The local north, east, down unit vectors (Earth-fixed) at lat, lon (deg). */
static void ned_axes(double lat, double lon, double n[3], double e[3], double d[3]) {
  const double sf = sin(lat * kRad), cf = cos(lat * kRad), sl = sin(lon * kRad), cl = cos(lon * kRad);
  n[0] = -sf * cl, n[1] = -sf * sl, n[2] = cf;
  e[0] = -sl, e[1] = cl, e[2] = 0;
  d[0] = -cf * cl, d[1] = -cf * sl, d[2] = -sf;
}

int main(void) {
  const double lat = 40.0, lon = -105.0, height = 10000.0, h = 60.0, p = 5.0, r = 10.0;
  const double v_ned[3] = {200.0, 50.0, -5.0};
  double q[4], n[3], e[3], d[3], nose[3], wing[3], axis[3], body_x[3] = {1, 0, 0}, body_y[3] = {0, 1, 0};
  eoir_engine eng = NULL;
  eoir_time t;
  eoir_state s, out, ef, ef_later;
  int i;

  OK(eoir_engine_create(NULL, &eng));
  OK(eoir_time_from_iso("2010-08-25T18:00:00Z", &t));
  OK(eoir_engine_set_time(eng, &t));
  OK(eoir_object_add(eng, EOIR_KIND_AIRCRAFT, "Jet"));
  hpr_quaternion(h, p, r, q);
  s = state_at(EOIR_FRAME_GEODETIC_NED, lat, lon, height);
  for (i = 0; i < 3; ++i) s.velocity[i] = v_ned[i];
  for (i = 0; i < 4; ++i) s.attitude[i] = q[i];
  s.angular_velocity[2] = 0.01; /* a turn to the right: yaw about down */
  OK(eoir_object_set_state(eng, "Jet", NULL, &s));

  /* Read back in the same frame. */
  out = state_at(EOIR_FRAME_GEODETIC_NED, 0, 0, 0);
  OK(eoir_object_get_state(eng, "Jet", &out));
  NEAR_ABS(out.position[0], lat, 1e-10);
  NEAR_ABS(out.position[1], lon, 1e-10);
  NEAR_ABS(out.position[2], height, 1e-6);
  for (i = 0; i < 3; ++i) NEAR_ABS(out.velocity[i], v_ned[i], 1e-9);
  {
    const double sign = out.attitude[0] * q[0] < 0 ? -1.0 : 1.0;
    for (i = 0; i < 4; ++i) NEAR_ABS(sign * out.attitude[i], q[i], 1e-12);
  }
  NEAR_ABS(out.angular_velocity[0], 0.0, 1e-15);
  NEAR_ABS(out.angular_velocity[1], 0.0, 1e-15);
  NEAR_ABS(out.angular_velocity[2], 0.01, 1e-15);

  /* Earth-fixed: velocity, nose and right wing from the closed-form axes. */
  ned_axes(lat, lon, n, e, d);
  ef = state_at(EOIR_FRAME_EARTH_FIXED, 0, 0, 0);
  OK(eoir_object_get_state(eng, "Jet", &ef));
  for (i = 0; i < 3; ++i) {
    NEAR_ABS(ef.velocity[i], v_ned[0] * n[i] + v_ned[1] * e[i] + v_ned[2] * d[i], 1e-9);
    nose[i] = cos(h * kRad) * cos(p * kRad) * n[i] + sin(h * kRad) * cos(p * kRad) * e[i] - sin(p * kRad) * d[i];
    wing[i] = (cos(h * kRad) * sin(p * kRad) * sin(r * kRad) - sin(h * kRad) * cos(r * kRad)) * n[i] +
              (sin(h * kRad) * sin(p * kRad) * sin(r * kRad) + cos(h * kRad) * cos(r * kRad)) * e[i] +
              cos(p * kRad) * sin(r * kRad) * d[i];
    NEAR_ABS(ef.angular_velocity[i], 0.01 * d[i], 1e-15);
  }
  rotate(ef.attitude, body_x, axis);
  for (i = 0; i < 3; ++i) NEAR_ABS(axis[i], nose[i], 1e-12);
  rotate(ef.attitude, body_y, axis);
  for (i = 0; i < 3; ++i) NEAR_ABS(axis[i], wing[i], 1e-12);
  /* The GEODETIC frame gives the same place. */
  out = state_at(EOIR_FRAME_GEODETIC, 0, 0, 0);
  OK(eoir_object_get_state(eng, "Jet", &out));
  NEAR_ABS(out.position[0], lat, 1e-10);
  NEAR_ABS(out.position[2], height, 1e-6);

  /* Extrapolated as an Earth-fixed state: a straight line there. */
  t.jd2 += 10.0 / 86400.0;
  OK(eoir_engine_set_time(eng, &t));
  ef_later = state_at(EOIR_FRAME_EARTH_FIXED, 0, 0, 0);
  OK(eoir_object_get_state(eng, "Jet", &ef_later));
  for (i = 0; i < 3; ++i) NEAR_ABS(ef_later.position[i], ef.position[i] + 10.0 * ef.velocity[i], 1e-4);

  /* Bad input names the field. */
  s = state_at(EOIR_FRAME_GEODETIC_NED, 95.0, 0.0, 0.0);
  FAILS(eoir_object_set_state(eng, "Jet", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "position[0] (latitude)");
  s = state_at(EOIR_FRAME_GEODETIC_NED, 0.0, 0.0, 0.0 / 0.0);
  FAILS(eoir_object_set_state(eng, "Jet", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "position[2] (height)");
  s = state_at(EOIR_FRAME_GEODETIC_NED, 0.0, 0.0, 0.0);
  s.attitude[0] = 2.0;
  FAILS(eoir_object_set_state(eng, "Jet", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "attitude");
  s = state_at(4, 0.0, 0.0, 0.0);
  FAILS(eoir_object_set_state(eng, "Jet", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "frame");
  out = state_at(4, 0, 0, 0);
  FAILS(eoir_object_get_state(eng, "Jet", &out), EOIR_ERR_OUT_OF_RANGE, "frame");

  eoir_engine_destroy(eng);
  return CHECK_SUMMARY();
}
