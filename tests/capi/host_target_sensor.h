/* A small scene for render tests of the C ABI. */
#ifndef EOIR_TEST_HOST_TARGET_SENSOR_H
#define EOIR_TEST_HOST_TARGET_SENSOR_H
#include "table3_sensor.h"
/* At 2010-08-25T18:00Z: satellite "Host" at 7000 km on +x J2000, satellite
 * "Target" 50 km from it along +z, and on Host the Table 3 sensor `sensor`
 * with 16 x 16 pixels. */
static void add_host_target_sensor(eoir_engine e, const char* sensor) {
  eoir_state s;
  eoir_time t;
  OK(eoir_time_from_iso("2010-08-25T18:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Host"));
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.attitude[0] = 1;
  s.position[0] = 7000e3;
  OK(eoir_object_set_state(e, "Host", NULL, &s));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Target"));
  s.position[2] = 50e3;
  OK(eoir_object_set_state(e, "Target", NULL, &s));
  add_table3_sensor(e, "Host", sensor);
  OK(eoir_set_integer(e, sensor, "horizontal_pixels", 16));
  OK(eoir_set_integer(e, sensor, "vertical_pixels", 16));
}
#endif
