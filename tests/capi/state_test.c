/* C ABI: time scales, states in the three frames, and bad states. */
#include "check.h"

static void time_scales(void) {
  eoir_engine e = NULL;
  eoir_time t, back;
  char iso[64];
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T18:00:00Z", &t));
  CHECK(t.scale == EOIR_TIME_UTC);
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_engine_get_time(e, EOIR_TIME_UTC, &back));
  NEAR_REL((back.jd1 - t.jd1) + (back.jd2 - t.jd2) + 1.0, 1.0, 1e-11); /* < 1 us */
  OK(eoir_time_to_iso(&back, iso, sizeof iso));
  CHECK(strcmp(iso, "2010-08-25T18:00:00.000Z") == 0);
  /* TT - UTC = 66.184 s in 2010 (34 leap seconds + 32.184 s) */
  OK(eoir_engine_get_time(e, EOIR_TIME_TT, &back));
  NEAR_REL(((back.jd1 - t.jd1) + (back.jd2 - t.jd2)) * 86400.0, 66.184, 1e-6);
  FAILS(eoir_time_from_iso("2010-13-45T99:00:00Z", &t), EOIR_ERR_OUT_OF_RANGE, "time");
  FAILS(eoir_time_from_iso("yesterday", &t), EOIR_ERR_OUT_OF_RANGE, "ISO-8601");
  FAILS(eoir_time_to_iso(&back, iso, 5), EOIR_ERR_BUFFER_TOO_SMALL, "capacity");
  t.jd2 = 0.0 / 0.0;
  FAILS(eoir_engine_set_time(e, &t), EOIR_ERR_OUT_OF_RANGE, "time.jd2");
  t.jd2 = 0.0;
  t.scale = 17;
  FAILS(eoir_engine_set_time(e, &t), EOIR_ERR_OUT_OF_RANGE, "time.scale");
  eoir_engine_destroy(e);
}

static void frames(void) {
  eoir_engine e = NULL;
  eoir_time t;
  eoir_state s, out;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T18:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Aircraft1"));
  FAILS(eoir_object_get_state(e, "Aircraft1", NULL), EOIR_ERR_NULL_ARGUMENT, "state");
  out = state_at(EOIR_FRAME_J2000, 0, 0, 0);
  FAILS(eoir_object_get_state(e, "Aircraft1", &out), EOIR_ERR_NO_STATE, "Aircraft1");
  /* geodetic in, geodetic out (GeographicLib round trip) */
  s = state_at(EOIR_FRAME_GEODETIC, 33.705, -118.294, 1600.0);
  OK(eoir_object_set_state(e, "Aircraft1", NULL, &s));
  out = state_at(EOIR_FRAME_GEODETIC, 0, 0, 0);
  OK(eoir_object_get_state(e, "Aircraft1", &out));
  NEAR_REL(out.position[0], 33.705, 1e-9);
  NEAR_REL(out.position[1], -118.294, 1e-9);
  NEAR_REL(out.position[2], 1600.0, 1e-6);
  /* J2000 radius equals Earth-fixed radius */
  out = state_at(EOIR_FRAME_J2000, 0, 0, 0);
  OK(eoir_object_get_state(e, "Aircraft1", &out));
  {
    eoir_state ef = state_at(EOIR_FRAME_EARTH_FIXED, 0, 0, 0);
    double rj, re;
    OK(eoir_object_get_state(e, "Aircraft1", &ef));
    rj = sqrt(out.position[0] * out.position[0] + out.position[1] * out.position[1] + out.position[2] * out.position[2]);
    re = sqrt(ef.position[0] * ef.position[0] + ef.position[1] * ef.position[1] + ef.position[2] * ef.position[2]);
    NEAR_REL(rj, re, 1e-12);
    /* a fixed point on the Earth moves at omega * r cos(lat) in J2000 */
    NEAR_REL(sqrt(out.velocity[0] * out.velocity[0] + out.velocity[1] * out.velocity[1] +
                  out.velocity[2] * out.velocity[2]),
             7.292115146706979e-5 * sqrt(ef.position[0] * ef.position[0] + ef.position[1] * ef.position[1]), 1e-9);
  }
  /* constant-velocity extrapolation in J2000 */
  s = state_at(EOIR_FRAME_J2000, 7000e3, 0, 0);
  s.velocity[1] = 7500.0;
  OK(eoir_object_set_state(e, "Aircraft1", NULL, &s));
  t.jd2 += 10.0 / 86400.0;
  OK(eoir_engine_set_time(e, &t));
  out = state_at(EOIR_FRAME_J2000, 0, 0, 0);
  OK(eoir_object_get_state(e, "Aircraft1", &out));
  NEAR_REL(out.position[1], 75000.0, 1e-6);
  /* central bodies: the Moon about 356,000-407,000 km away; they refuse states */
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Moon"));
  out = state_at(EOIR_FRAME_J2000, 0, 0, 0);
  OK(eoir_object_get_state(e, "Moon", &out));
  {
    double r = sqrt(out.position[0] * out.position[0] + out.position[1] * out.position[1] +
                    out.position[2] * out.position[2]);
    CHECK(r > 356e6 && r < 407e6);
  }
  out = state_at(EOIR_FRAME_J2000, 0, 0, 0);
  OK(eoir_object_get_state(e, "Sun", &out));
  {
    double r = sqrt(out.position[0] * out.position[0] + out.position[1] * out.position[1] +
                    out.position[2] * out.position[2]);
    NEAR_REL(r, 1.0108 * 1.495978707e11, 0.001); /* 1.0108 AU on 25 Aug 2010 (almanac) */
  }
  FAILS(eoir_object_set_state(e, "Moon", NULL, &s), EOIR_ERR_NOT_ALLOWED, "Moon");
  eoir_engine_destroy(e);
}

static void bad_states(void) {
  eoir_engine e = NULL;
  eoir_state s = state_at(EOIR_FRAME_J2000, 7000e3, 0, 0);
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite1"));
  s.position[1] = 0.0 / 0.0;
  FAILS(eoir_object_set_state(e, "Satellite1", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "position[1]");
  s.position[1] = 0.0;
  s.velocity[2] = 1.0 / 0.0;
  FAILS(eoir_object_set_state(e, "Satellite1", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "velocity[2]");
  s.velocity[2] = 0.0;
  s.attitude[0] = 0.9;
  FAILS(eoir_object_set_state(e, "Satellite1", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "attitude");
  s.attitude[0] = 1.0;
  s.frame = 7;
  FAILS(eoir_object_set_state(e, "Satellite1", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "frame");
  s.frame = EOIR_FRAME_GEODETIC;
  s.position[0] = 91.0;
  FAILS(eoir_object_set_state(e, "Satellite1", NULL, &s), EOIR_ERR_OUT_OF_RANGE, "latitude");
  s.frame = EOIR_FRAME_J2000;
  s.struct_size = 8;
  FAILS(eoir_object_set_state(e, "Satellite1", NULL, &s), EOIR_ERR_STRUCT_SIZE, "state.struct_size");
  s.struct_size = sizeof s;
  FAILS(eoir_object_set_state(e, "Nobody", NULL, &s), EOIR_ERR_UNKNOWN_NAME, "Nobody");
  eoir_engine_destroy(e);
}

int main(void) {
  time_scales();
  frames();
  bad_states();
  return CHECK_SUMMARY();
}
