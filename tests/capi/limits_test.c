/* C ABI: the object limits set at run time (issue 23 item 3; README "Object
 * limits"). The default profile is spec 3.1's (16 satellites, 6 vehicles,
 * 6 missiles, 6 sensors); a raised profile holds 10,000 satellites; bad
 * values are refused naming the field and change nothing; a saved state
 * carries its limits and every satellite; the per-frame truth lists every
 * satellite in the field. */
#include <stdlib.h>
#include <unistd.h>

#include "check.h"

static eoir_limits limits_of(eoir_engine e) {
  eoir_limits l;
  memset(&l, 0, sizeof l);
  l.struct_size = sizeof l;
  OK(eoir_engine_get_limits(e, &l));
  return l;
}

static void default_profile(void) {
  eoir_engine e = NULL;
  eoir_limits l;
  char name[32];
  int i;
  OK(eoir_engine_create(NULL, &e));
  l = limits_of(e);
  CHECK(l.max_satellites == EOIR_MAX_SATELLITES && l.max_satellites == 16);
  CHECK(l.max_vehicles == EOIR_MAX_VEHICLES && l.max_vehicles == 6);
  CHECK(l.max_sites == EOIR_MAX_SITES);
  CHECK(l.max_missiles == EOIR_MAX_MISSILES && l.max_missiles == 6);
  CHECK(l.max_sensors == EOIR_MAX_SENSORS && l.max_sensors == 6);
  for (i = 0; i < 16; ++i) {
    snprintf(name, sizeof name, "Sat%d", i + 1);
    OK(eoir_object_add(e, EOIR_KIND_SATELLITE, name));
  }
  FAILS(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat17"), EOIR_ERR_LIMIT_EXCEEDED, "max_satellites");
  FAILS(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat17"), EOIR_ERR_LIMIT_EXCEEDED, "at most 16 satellites");
  eoir_engine_destroy(e);
}

static void bad_values(void) {
  eoir_engine e = NULL;
  eoir_limits l, before;
  int i;
  char name[32];
  OK(eoir_engine_create(NULL, &e));
  before = limits_of(e);
  FAILS(eoir_engine_set_limits(e, NULL), EOIR_ERR_NULL_ARGUMENT, "limits");
  FAILS(eoir_engine_get_limits(e, NULL), EOIR_ERR_NULL_ARGUMENT, "limits_out");
  FAILS(eoir_engine_set_limits(NULL, &before), EOIR_ERR_NULL_ARGUMENT, "engine");
  l = before;
  l.struct_size = 8;
  FAILS(eoir_engine_set_limits(e, &l), EOIR_ERR_STRUCT_SIZE, "limits.struct_size");
  l = before;
  l.max_satellites = 0;
  FAILS(eoir_engine_set_limits(e, &l), EOIR_ERR_OUT_OF_RANGE, "max_satellites");
  l = before;
  l.max_satellites = EOIR_CEILING_SATELLITES + 1;
  FAILS(eoir_engine_set_limits(e, &l), EOIR_ERR_OUT_OF_RANGE, "max_satellites");
  l = before;
  l.max_vehicles = 0;
  FAILS(eoir_engine_set_limits(e, &l), EOIR_ERR_OUT_OF_RANGE, "max_vehicles");
  l = before;
  l.max_sites = EOIR_CEILING_SITES + 1;
  FAILS(eoir_engine_set_limits(e, &l), EOIR_ERR_OUT_OF_RANGE, "max_sites");
  l = before;
  l.max_missiles = 0xffffffffu;
  FAILS(eoir_engine_set_limits(e, &l), EOIR_ERR_OUT_OF_RANGE, "max_missiles");
  l = before;
  l.max_sensors = EOIR_CEILING_SENSORS + 1;
  FAILS(eoir_engine_set_limits(e, &l), EOIR_ERR_OUT_OF_RANGE, "max_sensors");
  /* below what the engine holds: refused, the limits stay */
  for (i = 0; i < 5; ++i) {
    snprintf(name, sizeof name, "Sat%d", i + 1);
    OK(eoir_object_add(e, EOIR_KIND_SATELLITE, name));
  }
  l = before;
  l.max_satellites = 4;
  l.max_sensors = 100; /* a good value beside a bad one changes nothing either */
  FAILS(eoir_engine_set_limits(e, &l), EOIR_ERR_NOT_ALLOWED, "max_satellites");
  l = limits_of(e);
  CHECK(memcmp(&l, &before, sizeof l) == 0);
  /* lowered to exactly what it holds: the next is refused */
  l.max_satellites = 5;
  OK(eoir_engine_set_limits(e, &l));
  FAILS(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat6"), EOIR_ERR_LIMIT_EXCEEDED, "max_satellites");
  eoir_engine_destroy(e);
}

static void raised_profile(void) {
  eoir_engine e = NULL;
  eoir_limits l;
  char name[32];
  int i, failures = 0;
  size_t count = 0;
  OK(eoir_engine_create(NULL, &e));
  l = limits_of(e);
  l.max_satellites = 10000;
  l.max_vehicles = 1000;
  l.max_sensors = 50;
  OK(eoir_engine_set_limits(e, &l));
  l = limits_of(e);
  CHECK(l.max_satellites == 10000 && l.max_vehicles == 1000 && l.max_sensors == 50);
  CHECK(l.max_missiles == EOIR_MAX_MISSILES && l.max_sites == EOIR_MAX_SITES);
  for (i = 0; i < 10000; ++i) {
    snprintf(name, sizeof name, "Sat%05d", i);
    failures += eoir_object_add(e, EOIR_KIND_SATELLITE, name) != EOIR_OK;
  }
  CHECK(failures == 0);
  OK(eoir_object_count(e, &count));
  CHECK(count == 10001); /* and the Sun */
  FAILS(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat10000"), EOIR_ERR_LIMIT_EXCEEDED, "at most 10000 satellites");
  for (i = 0; i < 1000; ++i) {
    snprintf(name, sizeof name, "Car%04d", i);
    failures += eoir_object_add(e, EOIR_KIND_GROUND_VEHICLE, name) != EOIR_OK;
  }
  CHECK(failures == 0);
  FAILS(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Plane"), EOIR_ERR_LIMIT_EXCEEDED, "max_vehicles");
  /* names stay unique at this size, and removal keeps the registry whole */
  FAILS(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Sun"), EOIR_ERR_ALREADY_EXISTS, "Sun");
  OK(eoir_object_remove(e, "Sat05000"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat10000"));
  FAILS(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat05000"), EOIR_ERR_LIMIT_EXCEEDED, "max_satellites");
  {
    char shape[32];
    OK(eoir_set_string(e, "Sat09999", "shape", "box"));
    OK(eoir_get_string(e, "Sat09999", "shape", shape, sizeof shape));
    CHECK(strcmp(shape, "box") == 0);
    OK(eoir_get_string(e, "Sat10000", "shape", shape, sizeof shape));
    CHECK(strcmp(shape, "box") != 0);
  }
  eoir_engine_destroy(e);
}

/* 40 one-metre spheres 1000 km in front of a sensor on a GEO-radius host,
 * on an 8 x 5 grid 10 km apart (within +-2.3 deg of the boresight of a
 * 10 deg field); every one of them is in the field. */
enum { kRows = 5, kColumns = 8, kSatellites = kRows * kColumns };

static void build_field(eoir_engine e) {
  eoir_time t;
  eoir_state s;
  eoir_limits l;
  char name[32];
  int i;
  l = limits_of(e);
  l.max_satellites = 100;
  OK(eoir_engine_set_limits(e, &l));
  OK(eoir_time_from_iso("2010-03-30T02:25:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_J2000;
  s.attitude[0] = 1;
  s.position[0] = 42164.2e3;
  s.velocity[1] = 3074.7;
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Host"));
  OK(eoir_set_string(e, "Host", "shape", "none"));
  OK(eoir_object_set_state(e, "Host", NULL, &s));
  for (i = 0; i < kSatellites; ++i) {
    snprintf(name, sizeof name, "Sat%02d", i);
    OK(eoir_object_add(e, EOIR_KIND_SATELLITE, name));
    OK(eoir_set_string(e, name, "shape", "sphere"));
    OK(eoir_set_number(e, name, "temperature_K", 250.0 + i));
    s.position[0] = 42164.2e3 - 1000e3;
    s.position[1] = (i % kColumns - 3.5) * 10e3;
    s.position[2] = (i / kColumns - 2.0) * 10e3;
    OK(eoir_object_set_state(e, name, NULL, &s));
  }
  OK(eoir_sensor_add(e, "Sensor", "Host"));
  OK(eoir_set_integer(e, "Sensor", "horizontal_pixels", 64));
  OK(eoir_set_integer(e, "Sensor", "vertical_pixels", 64));
  OK(eoir_set_number(e, "Sensor", "horizontal_fov_deg", 10.0));
  OK(eoir_set_number(e, "Sensor", "vertical_fov_deg", 10.0));
  /* body +z along -x J2000: a turn of -90 deg about y */
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_J2000;
  s.attitude[0] = 0.70710678118654752;
  s.attitude[2] = -0.70710678118654752;
  OK(eoir_object_set_state(e, "Sensor", NULL, &s));
}

/* How many truth rows of the last frame are objects, and whether each of
 * the 40 satellites is listed exactly once. */
static int truth_lists_all(eoir_engine e) {
  size_t n = 0, k;
  int seen[kSatellites];
  int objects = 0, i, once = 1;
  memset(seen, 0, sizeof seen);
  OK(eoir_truth_count(e, "Sensor", &n));
  for (k = 0; k < n; ++k) {
    eoir_truth t;
    memset(&t, 0, sizeof t);
    t.struct_size = sizeof t;
    OK(eoir_truth_get(e, "Sensor", k, &t));
    if (t.kind != EOIR_TRUTH_OBJECT) continue;
    ++objects;
    if (strncmp(t.object, "Sat", 3) == 0) {
      i = atoi(t.object + 3);
      if (i >= 0 && i < kSatellites) ++seen[i];
    }
  }
  for (i = 0; i < kSatellites; ++i) once = once && seen[i] == 1;
  return objects == kSatellites && once;
}

static void save_restore_and_truth(void) {
  char dir[] = "/tmp/eoir_limits_XXXXXX";
  char path[256];
  eoir_engine e = NULL, f = NULL;
  eoir_limits l;
  eoir_state a, b;
  size_t count_e = 0, count_f = 0;
  int i;
  CHECK(mkdtemp(dir) != NULL);
  snprintf(path, sizeof path, "%s/many.scd", dir);
  OK(eoir_engine_create(NULL, &e));
  build_field(e);
  OK(eoir_render(e, "Sensor"));
  CHECK(truth_lists_all(e));
  OK(eoir_state_save(e, path));

  /* restored into an engine of the default profile: the file's limits and
   * all 41 satellites come back */
  OK(eoir_engine_create(NULL, &f));
  OK(eoir_state_load(f, path));
  l = limits_of(f);
  CHECK(l.max_satellites == 100 && l.max_vehicles == EOIR_MAX_VEHICLES);
  OK(eoir_object_count(e, &count_e));
  OK(eoir_object_count(f, &count_f));
  CHECK(count_e == count_f && count_f == 1 + 1 + kSatellites + 1);
  for (i = 0; i < kSatellites; ++i) {
    char name[32];
    double T = 0;
    snprintf(name, sizeof name, "Sat%02d", i);
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    a.struct_size = b.struct_size = sizeof a;
    OK(eoir_object_get_state(e, name, &a));
    OK(eoir_object_get_state(f, name, &b));
    CHECK(memcmp(a.position, b.position, sizeof a.position) == 0);
    OK(eoir_get_number(f, name, "temperature_K", &T));
    CHECK(T == 250.0 + i);
  }
  OK(eoir_render(f, "Sensor"));
  CHECK(truth_lists_all(f));
  eoir_engine_destroy(f);
  eoir_engine_destroy(e);
  remove(path);
  rmdir(dir);
}

int main(void) {
  default_profile();
  bad_values();
  raised_profile();
  save_restore_and_truth();
  return CHECK_SUMMARY();
}
