/* The sensor property motion_substeps through the C ABI (issue 23 item 5;
 * beyond spec 5.1 assumption 6), C99: 1 by default; 1..64 accepted, other
 * values refused naming the property and leaving it unchanged; saved and
 * restored with the state; with nothing moving, a frame of 4 sub-steps is
 * the frame of 1 (the mean of four equal scenes) to 1e-9; a frame in strips
 * (scene_memory_max_mib 0) takes its sub-steps strip by strip: the same frame
 * to 1e-9, without a scene display. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#include "host_target_sensor.h"

#define N (16 * 16)

int main(void) {
  eoir_engine e = NULL, e2 = NULL;
  static double one[N], four[N], strips[N];
  eoir_image_info info;
  char dir[] = "/tmp/eoir_substeps_XXXXXX", path[256];
  int64_t n = 0;
  double total = 0, largest = 0;
  int i, close = 1, same = 1;

  OK(eoir_engine_create(NULL, &e));
  add_host_target_sensor(e, "Cam");

  /* Off (1) by default; bad values refused naming the property. */
  OK(eoir_get_integer(e, "Cam", "motion_substeps", &n));
  CHECK(n == 1);
  FAILS(eoir_set_integer(e, "Cam", "motion_substeps", 0), EOIR_ERR_OUT_OF_RANGE, "motion_substeps");
  FAILS(eoir_set_integer(e, "Cam", "motion_substeps", -3), EOIR_ERR_OUT_OF_RANGE, "motion_substeps");
  FAILS(eoir_set_integer(e, "Cam", "motion_substeps", 65), EOIR_ERR_OUT_OF_RANGE, "motion_substeps");
  FAILS(eoir_set_number(e, "Cam", "motion_substeps", NAN), EOIR_ERR_OUT_OF_RANGE, "motion_substeps");
  FAILS(eoir_set_number(e, "Cam", "motion_substeps", 2.5), EOIR_ERR_OUT_OF_RANGE, "motion_substeps");
  FAILS(eoir_set_bool(e, "Cam", "motion_substeps", 1), EOIR_ERR_TYPE_MISMATCH, "motion_substeps");
  FAILS(eoir_set_integer(e, "Host", "motion_substeps", 4), EOIR_ERR_UNKNOWN_NAME, "motion_substeps");
  OK(eoir_get_integer(e, "Cam", "motion_substeps", &n));
  CHECK(n == 1);
  OK(eoir_set_integer(e, "Cam", "motion_substeps", 64));
  OK(eoir_set_integer(e, "Cam", "motion_substeps", 1));

  /* Nothing moves: 4 sub-steps give the frame of 1. */
  OK(eoir_set_bool(e, "Cam", "noise_enabled", 0));
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, one, N));
  OK(eoir_set_integer(e, "Cam", "motion_substeps", 4));
  OK(eoir_get_integer(e, "Cam", "motion_substeps", &n));
  CHECK(n == 4);
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, four, N));
  for (i = 0; i < N; ++i) {
    total += one[i];
    largest = one[i] > largest ? one[i] : largest;
  }
  CHECK(total > 0);
  for (i = 0; i < N; ++i) close = close && isfinite(four[i]) && fabs(four[i] - one[i]) <= 1e-9 * largest;
  CHECK(close);

  /* In strips, strip by strip: the same frame, without a scene display. */
  OK(eoir_set_number(e, "Cam", "scene_memory_max_mib", 0));
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, strips, N));
  for (i = 0; i < N; ++i) same = same && fabs(strips[i] - four[i]) <= 1e-9 * largest;
  CHECK(same);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  FAILS(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SCENE_DISPLAY, &info), EOIR_ERR_NO_STATE, "scene_memory_max_mib");
  OK(eoir_set_number(e, "Cam", "scene_memory_max_mib", 1024));

  /* Saved and restored with the state. */
  CHECK(mkdtemp(dir) != NULL);
  snprintf(path, sizeof path, "%s/substeps.scd", dir);
  OK(eoir_state_save(e, path));
  OK(eoir_engine_create(NULL, &e2));
  OK(eoir_state_load(e2, path));
  OK(eoir_get_integer(e2, "Cam", "motion_substeps", &n));
  CHECK(n == 4);
  unlink(path);
  rmdir(dir);

  eoir_engine_destroy(e2);
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
