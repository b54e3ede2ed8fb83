/* C ABI: engine lifetime, version, object registration and the limits of
 * spec 3.1. */
#include <stdio.h>

#include "check.h"

static void version(void) {
  CHECK(eoir_version() / 10000u == EOIR_VERSION_MAJOR);
  CHECK(eoir_version_string()[0] == (char)(48 + EOIR_VERSION_MAJOR) && eoir_version() % 10000u / 100u == EOIR_VERSION_MINOR);
}

static void lifetime(void) {
  eoir_engine e = NULL;
  eoir_engine_desc bad, v1;
  memset(&bad, 0, sizeof bad);
  FAILS(eoir_engine_create(NULL, NULL), EOIR_ERR_NULL_ARGUMENT, "engine_out");
  FAILS(eoir_engine_create(&bad, &e), EOIR_ERR_STRUCT_SIZE, "desc.struct_size");
  CHECK(e == NULL);
  /* A host compiled against ABI 1.0 passes the 16-byte struct: accepted. */
  memset(&v1, 0, sizeof v1);
  v1.struct_size = 16;
  v1.seed = 7;
  OK(eoir_engine_create(&v1, &e));
  eoir_engine_destroy(e);
  e = NULL;
  /* threads are bounded */
  v1.threads = 1000000000u;
  FAILS(eoir_engine_create(&v1, &e), EOIR_ERR_OUT_OF_RANGE, "desc.threads");
  v1.threads = 0;
  OK(eoir_engine_create(NULL, &e));
  eoir_engine_destroy(e);
  eoir_engine_destroy(NULL); /* accepted */
}

static void limits(void) {
  eoir_engine e = NULL;
  char name[32];
  int i;
  size_t count = 0;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_count(e, &count));
  CHECK(count == 1); /* the Sun */
  FAILS(eoir_object_remove(e, "Sun"), EOIR_ERR_NOT_ALLOWED, "Sun");
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Moon"));
  OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  FAILS(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Pluto"), EOIR_ERR_UNKNOWN_NAME, "Pluto");
  FAILS(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"), EOIR_ERR_ALREADY_EXISTS, "Earth");
  FAILS(eoir_object_add(e, 99, "X"), EOIR_ERR_OUT_OF_RANGE, "kind");
  FAILS(eoir_object_add(e, EOIR_KIND_SATELLITE, ""), EOIR_ERR_OUT_OF_RANGE, "name");
  FAILS(eoir_object_add(e, EOIR_KIND_SATELLITE, NULL), EOIR_ERR_NULL_ARGUMENT, "name");
  for (i = 0; i < EOIR_MAX_SATELLITES; ++i) {
    snprintf(name, sizeof name, "Satellite%d", i + 1);
    OK(eoir_object_add(e, EOIR_KIND_SATELLITE, name));
  }
  FAILS(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite17"), EOIR_ERR_LIMIT_EXCEEDED, "16 satellites");
  for (i = 0; i < EOIR_MAX_VEHICLES; ++i) {
    snprintf(name, sizeof name, "Vehicle%d", i + 1);
    OK(eoir_object_add(e, i % 2 ? EOIR_KIND_AIRCRAFT : EOIR_KIND_GROUND_VEHICLE, name));
  }
  FAILS(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Aircraft7"), EOIR_ERR_LIMIT_EXCEEDED, "aircraft plus ground");
  for (i = 0; i < EOIR_MAX_MISSILES; ++i) {
    snprintf(name, sizeof name, "Missile%d", i + 1);
    OK(eoir_object_add(e, EOIR_KIND_MISSILE, name));
  }
  FAILS(eoir_object_add(e, EOIR_KIND_MISSILE, "Missile7"), EOIR_ERR_LIMIT_EXCEEDED, "missiles");
  OK(eoir_set_integer(e, "Missile1", "stages", EOIR_MAX_MISSILE_STAGES));
  FAILS(eoir_set_integer(e, "Missile1", "stages", EOIR_MAX_MISSILE_STAGES + 1), EOIR_ERR_LIMIT_EXCEEDED, "stages");
  for (i = 0; i < EOIR_MAX_SENSORS; ++i) {
    snprintf(name, sizeof name, "Sensor%d", i + 1);
    OK(eoir_sensor_add(e, name, i % 2 ? "Earth" : "Satellite1"));
  }
  FAILS(eoir_sensor_add(e, "Sensor7", "Satellite1"), EOIR_ERR_LIMIT_EXCEEDED, "sensors");
  FAILS(eoir_object_add(e, EOIR_KIND_SENSOR, "Sensor8"), EOIR_ERR_OUT_OF_RANGE, "eoir_sensor_add");
  /* removing a parent removes its sensors; then a sensor can be added again */
  OK(eoir_object_remove(e, "Satellite1"));
  OK(eoir_object_count(e, &count));
  CHECK(count == 1 + 3 + 15 + 6 + 6 + 3);
  OK(eoir_sensor_add(e, "Sensor7", "Satellite2"));
  FAILS(eoir_sensor_add(e, "Sensor8", "NoSuchParent"), EOIR_ERR_UNKNOWN_NAME, "NoSuchParent");
  FAILS(eoir_sensor_add(e, "Sensor9", "Stars"), EOIR_ERR_NOT_ALLOWED, "Stars");
  {
    const char* n = NULL;
    int32_t kind = 0;
    OK(eoir_object_at(e, 0, &n, &kind));
    CHECK(n && strcmp(n, "Sun") == 0 && kind == EOIR_KIND_CENTRAL_BODY);
    FAILS(eoir_object_at(e, 1000, &n, &kind), EOIR_ERR_OUT_OF_RANGE, "index");
  }
  eoir_engine_destroy(e);
}

int main(void) {
  version();
  lifetime();
  limits();
  return CHECK_SUMMARY();
}
