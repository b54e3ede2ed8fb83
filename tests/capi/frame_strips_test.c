/* Frames made in strips through the C ABI (issue 23 item 2): the fidelity
 * property scene_memory_max_mib is validated naming the field and saved with
 * the sensor; a frame made in strips has the whole frame's electrons (to
 * 1e-9 relative) and scene radiance, its scene display is EOIR_ERR_NO_STATE
 * naming the property, and a bad TMPDIR is EOIR_ERR_IO naming the folder. */
#include <stdlib.h>

#include "host_target_sensor.h"

#define N (16 * 16)

int main(void) {
  eoir_engine e = NULL;
  eoir_image_info info;
  static double whole[N], strips[N], radiance_whole[64 * 64], radiance_strips[64 * 64];
  uint8_t display[64 * 64];
  double limit = -1, worst = 0, peak = 0;
  int i;

  OK(eoir_engine_create(NULL, &e));
  add_host_target_sensor(e, "Sensor1");
  OK(eoir_set_bool(e, "Sensor1", "noise_enabled", 0));
  FAILS(eoir_set_number(e, "Sensor1", "scene_memory_max_mib", NAN), EOIR_ERR_OUT_OF_RANGE, "scene_memory_max_mib");
  FAILS(eoir_set_number(e, "Sensor1", "scene_memory_max_mib", -1), EOIR_ERR_OUT_OF_RANGE, "scene_memory_max_mib");
  OK(eoir_get_number(e, "Sensor1", "scene_memory_max_mib", &limit));
  CHECK(limit == 1024.0);

  OK(eoir_render(e, "Sensor1"));
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SENSOR_MEAN, whole, N));
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SCENE_RADIANCE, radiance_whole, 64 * 64));

  OK(eoir_set_number(e, "Sensor1", "scene_memory_max_mib", 0));
  OK(eoir_render(e, "Sensor1"));
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SENSOR_MEAN, strips, N));
  for (i = 0; i < N; ++i) peak = fabs(whole[i]) > peak ? fabs(whole[i]) : peak;
  for (i = 0; i < N; ++i) {
    const double d = fabs(whole[i] - strips[i]) / (fabs(whole[i]) > 1e-6 * peak ? fabs(whole[i]) : 1e-6 * peak);
    worst = d > worst ? d : worst;
  }
  CHECK(peak > 0 && worst < 1e-9);
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SCENE_RADIANCE, radiance_strips, 64 * 64));
  CHECK(memcmp(radiance_whole, radiance_strips, sizeof radiance_whole) == 0);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  FAILS(eoir_image_info_get(e, "Sensor1", EOIR_IMAGE_SCENE_DISPLAY, &info), EOIR_ERR_NO_STATE, "scene_memory_max_mib");
  FAILS(eoir_image_get_bytes(e, "Sensor1", EOIR_IMAGE_SCENE_DISPLAY, display, sizeof display), EOIR_ERR_NO_STATE,
        "scene_memory_max_mib");
  OK(eoir_image_get_bytes(e, "Sensor1", EOIR_IMAGE_SENSOR_DISPLAY, display, sizeof display));

  /* No temporary folder: refused, naming it; the last frame stays. */
  setenv("TMPDIR", "/nonexistent/eoir-tmp", 1);
  FAILS(eoir_render(e, "Sensor1"), EOIR_ERR_IO, "/nonexistent/eoir-tmp");
  unsetenv("TMPDIR");
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SENSOR_MEAN, strips, N));
  CHECK(strips[N / 2] == whole[N / 2] || fabs(strips[N / 2] - whole[N / 2]) <= 1e-9 * peak);

  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
