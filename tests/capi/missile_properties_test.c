/* C ABI: a missile's stages, plumes and launch time (spec 4.3.6), bad values
 * refused with the field named, and the properties kept through save and
 * restore. */
#include "check.h"

static const char* two_stages =
    "[{\"length_m\": 18, \"radius_m\": 0.9, \"separation_s\": 60,"
    "  \"plume\": {\"temperature_K\": 1500, \"length_scale\": 3, \"width_scale\": 1.5}},"
    " {\"length_m\": 6, \"radius_m\": 0.6,"
    "  \"parts\": [{\"shape\": \"cylinder\", \"dimensions_m\": [0.6, 4], \"offset_m\": [0, 0, 2]},"
    "            {\"shape\": \"cone\", \"dimensions_m\": [0.6, 2], \"offset_m\": [0, 0, 5]}],"
    "  \"plume\": {\"spectrum\": \"sun\", \"on_s\": 2, \"off_s\": 80}}]";

int main(void) {
  eoir_engine e = NULL;
  int64_t n = 0;
  char s[2048];
  char path[] = "/tmp/eoir_missile_properties_XXXXXX";
  int fd;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_MISSILE, "Missile1"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite1"));

  /* good values */
  OK(eoir_set_string(e, "Missile1", "missile_stages", two_stages));
  OK(eoir_get_integer(e, "Missile1", "stages", &n));
  CHECK(n == 2); /* the count follows the stages */
  OK(eoir_set_integer(e, "Missile1", "stages", 2));
  OK(eoir_set_string(e, "Missile1", "launch_time_utc", "2026-01-01T00:00:00Z"));
  OK(eoir_get_string(e, "Missile1", "launch_time_utc", s, sizeof s));
  CHECK(strcmp(s, "2026-01-01T00:00:00Z") == 0);

  /* bad values name the field */
  FAILS(eoir_set_integer(e, "Missile1", "stages", 3), EOIR_ERR_NOT_ALLOWED, "stages");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages", "[{"), EOIR_ERR_OUT_OF_RANGE, "missile_stages");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages", "{}"), EOIR_ERR_OUT_OF_RANGE, "missile_stages");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages", "[{\"radius_m\": 1}]"), EOIR_ERR_OUT_OF_RANGE,
        "missile_stages[0].length_m");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages", "[{\"length_m\": -1, \"radius_m\": 1}]"),
        EOIR_ERR_OUT_OF_RANGE, "missile_stages[0].length_m");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages", "[{\"length_m\": 1e999, \"radius_m\": 1}]"),
        EOIR_ERR_OUT_OF_RANGE, "missile_stages");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages", "[{\"length_m\": 1, \"radius_m\": 1, \"fins\": 4}]"),
        EOIR_ERR_UNKNOWN_NAME, "missile_stages[0].fins");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages",
                        "[{\"length_m\": 1, \"radius_m\": 1}, {\"length_m\": 1, \"radius_m\": 1}]"),
        EOIR_ERR_OUT_OF_RANGE, "missile_stages[0].separation_s");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages",
                        "[{\"length_m\": 1, \"radius_m\": 1, \"separation_s\": 0}]"),
        EOIR_ERR_OUT_OF_RANGE, "missile_stages[0].separation_s");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages",
                        "[{\"length_m\": 10, \"radius_m\": 1, \"plume\": {\"width_scale\": 2}}]"),
        EOIR_ERR_OUT_OF_RANGE, "missile_stages[0].plume: give temperature_K");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages",
                        "[{\"length_m\": 10, \"radius_m\": 1, \"plume\": {\"temperature_K\": -5}}]"),
        EOIR_ERR_OUT_OF_RANGE, "missile_stages[0].plume.temperature_K");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages",
                        "[{\"length_m\": 10, \"radius_m\": 1, \"plume\": {\"temperature_K\": 900, \"colour\": 1}}]"),
        EOIR_ERR_UNKNOWN_NAME, "missile_stages[0].plume.colour");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages",
                        "[{\"length_m\": 1, \"radius_m\": 1, \"plume\": {\"temperature_K\": 900}}]"),
        EOIR_ERR_OUT_OF_RANGE, "missile_stages[0].plume"); /* length 1 m for a 1 m radius: no cone */
  FAILS(eoir_set_string(e, "Missile1", "missile_stages",
                        "[{\"length_m\": 10, \"radius_m\": 1, \"plume\": {\"temperature_K\": 900, \"on_s\": 5, "
                        "\"off_s\": 5}}]"),
        EOIR_ERR_OUT_OF_RANGE, "missile_stages[0].plume.off_s");
  FAILS(eoir_set_string(e, "Missile1", "missile_stages",
                        "[{\"length_m\": 10, \"radius_m\": 1, \"parts\": [{\"shape\": \"torus\"}]}]"),
        EOIR_ERR_UNKNOWN_NAME, "missile_stages[0].parts[0].shape");
  {
    /* 19 stages: one beyond EOIR_MAX_MISSILE_STAGES */
    char many[4096] = "[";
    int i;
    for (i = 0; i < 19; ++i)
      strcat(many, i ? ", {\"length_m\": 1, \"radius_m\": 1, \"separation_s\": 1}"
                     : "{\"length_m\": 1, \"radius_m\": 1, \"separation_s\": 1}");
    strcat(many, "]");
    FAILS(eoir_set_string(e, "Missile1", "missile_stages", many), EOIR_ERR_LIMIT_EXCEEDED, "missile_stages");
  }
  FAILS(eoir_set_string(e, "Missile1", "launch_time_utc", "yesterday"), EOIR_ERR_OUT_OF_RANGE, "launch_time_utc");
  FAILS(eoir_set_string(e, "Missile1", "launch_time_utc", "0100-01-01T00:00:00Z"), EOIR_ERR_OUT_OF_RANGE,
        "launch_time_utc");
  FAILS(eoir_set_string(e, "Satellite1", "missile_stages", "[]"), EOIR_ERR_UNKNOWN_NAME, "missile_stages");
  {
    /* the shape plume: a sphere and its tangent cone, longer than twice its radius */
    double dims[2] = {1.0, 2.0}, got[2] = {0, 0};
    size_t count = 0;
    OK(eoir_set_string(e, "Satellite1", "shape", "plume"));
    OK(eoir_get_array(e, "Satellite1", "dimensions_m", got, 2, &count));
    CHECK(count == 2 && got[1] > 2 * got[0]);
    FAILS(eoir_set_array(e, "Satellite1", "dimensions_m", dims, 2), EOIR_ERR_OUT_OF_RANGE, "dimensions_m[1] (length)");
    dims[1] = 0.0 / 0.0;
    FAILS(eoir_set_array(e, "Satellite1", "dimensions_m", dims, 2), EOIR_ERR_OUT_OF_RANGE, "dimensions_m[1]");
    dims[1] = 2.5;
    OK(eoir_set_array(e, "Satellite1", "dimensions_m", dims, 2));
  }
  /* a refused value leaves the last good one */
  OK(eoir_get_string(e, "Missile1", "missile_stages", s, sizeof s));
  CHECK(strcmp(s, two_stages) == 0);

  /* save and restore keep them */
  fd = mkstemp(path);
  CHECK(fd >= 0);
  OK(eoir_state_save(e, path));
  OK(eoir_object_remove(e, "Missile1"));
  OK(eoir_state_load(e, path));
  OK(eoir_get_string(e, "Missile1", "missile_stages", s, sizeof s));
  CHECK(strcmp(s, two_stages) == 0);
  OK(eoir_get_string(e, "Missile1", "launch_time_utc", s, sizeof s));
  CHECK(strcmp(s, "2026-01-01T00:00:00Z") == 0);
  OK(eoir_get_integer(e, "Missile1", "stages", &n));
  CHECK(n == 2);
  remove(path);
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
