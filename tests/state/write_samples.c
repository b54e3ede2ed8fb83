/* Writes a sample .scd and sensor file (argv[1], argv[2]) through the C ABI,
 * for the schema check of validate_schemas.py. */
#include "../capi/table3_sensor.h"

int main(int argc, char** argv) {
  eoir_engine e = NULL;
  eoir_state s;
  if (argc != 3) return 2;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Moon"));
  OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite1"));
  OK(eoir_object_add(e, EOIR_KIND_MISSILE, "Missile1"));
  OK(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Aircraft1"));
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_GEODETIC;
  s.position[0] = 10;
  s.position[2] = 1000;
  s.attitude[0] = 1;
  OK(eoir_object_set_state(e, "Aircraft1", NULL, &s));
  add_table3_sensor(e, "Satellite1", "Sensor1");
  OK(eoir_object_add(e, EOIR_KIND_SITE, "Site1"));
  OK(eoir_set_number(e, "Site1", "latitude_deg", -30.0));
  OK(eoir_sensor_add(e, "Sensor2", "Site1"));
  OK(eoir_sensor_point_azel(e, "Sensor2", 45.0, 30.0));
  OK(eoir_state_save(e, argv[1]));
  OK(eoir_sensor_save(e, "Sensor1", argv[2]));
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
