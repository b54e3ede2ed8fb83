/* The detector stage through the C ABI (1.7; issue 23 item 4, README
 * "Detector model"), C99: its sensor properties refuse bad input naming the
 * field, are saved and restored with the state; a frame rendered with it has
 * an ADU image (eoir_image_get_adu, EOIR_IMAGE_SENSOR_ADU) equal to
 * clamp(floor(e / gain + bias + 1/2), 0, 2^bits - 1) of its electron image,
 * electrons clipped at the full well, and image info with the detector's
 * gain, bias and levels; with the stage off the frame is the spec's, bit for
 * bit, and there is no ADU image. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#include "host_target_sensor.h"

#define N (16 * 16)

int main(void) {
  eoir_engine e = NULL, e2 = NULL;
  static double spec_e[N], spec_e2[N], el[N], adu_d[N];
  static uint32_t adu[N], small[4];
  const eoir_api_v1* api = NULL;
  const void* table = NULL;
  eoir_image_info info;
  char dir[] = "/tmp/eoir_detector_XXXXXX", path[256];
  double x = 0;
  int64_t bits = 0;
  int32_t on = 0;
  int i, same = 1, consistent = 1, within = 1, whole = 1;

  OK(eoir_engine_create(NULL, &e));
  add_host_target_sensor(e, "Cam");

  /* Off by default; bad input refused, naming the field. */
  OK(eoir_get_bool(e, "Cam", "detector_model", &on));
  CHECK(on == 0);
  FAILS(eoir_set_number(e, "Cam", "gain_e_per_adu", NAN), EOIR_ERR_OUT_OF_RANGE, "gain_e_per_adu");
  FAILS(eoir_set_number(e, "Cam", "gain_e_per_adu", -1.0), EOIR_ERR_OUT_OF_RANGE, "gain_e_per_adu");
  FAILS(eoir_set_number(e, "Cam", "gain_e_per_adu", 0.0), EOIR_ERR_OUT_OF_RANGE, "gain_e_per_adu");
  FAILS(eoir_set_number(e, "Cam", "gain_e_per_adu", INFINITY), EOIR_ERR_OUT_OF_RANGE, "gain_e_per_adu");
  FAILS(eoir_set_integer(e, "Cam", "adc_bits", 0), EOIR_ERR_OUT_OF_RANGE, "adc_bits");
  FAILS(eoir_set_integer(e, "Cam", "adc_bits", 33), EOIR_ERR_OUT_OF_RANGE, "adc_bits");
  FAILS(eoir_set_number(e, "Cam", "dark_current_e_s", -0.1), EOIR_ERR_OUT_OF_RANGE, "dark_current_e_s");
  FAILS(eoir_set_number(e, "Cam", "read_noise_e", NAN), EOIR_ERR_OUT_OF_RANGE, "read_noise_e");
  FAILS(eoir_set_number(e, "Cam", "full_well_e", 0.0), EOIR_ERR_OUT_OF_RANGE, "full_well_e");
  FAILS(eoir_set_number(e, "Cam", "bias_adu", -1.0), EOIR_ERR_OUT_OF_RANGE, "bias_adu");
  FAILS(eoir_set_number(e, "Cam", "prnu_fraction", 1.5), EOIR_ERR_OUT_OF_RANGE, "prnu_fraction");
  FAILS(eoir_set_number(e, "Cam", "hot_pixel_fraction", NAN), EOIR_ERR_OUT_OF_RANGE, "hot_pixel_fraction");
  FAILS(eoir_set_number(e, "Cam", "dead_pixel_fraction", -0.5), EOIR_ERR_OUT_OF_RANGE, "dead_pixel_fraction");
  FAILS(eoir_set_number(e, "Cam", "dsnu_e_s", NAN), EOIR_ERR_OUT_OF_RANGE, "dsnu_e_s");
  FAILS(eoir_set_integer(e, "Cam", "detector_pattern_seed", -1), EOIR_ERR_OUT_OF_RANGE, "detector_pattern_seed");
  OK(eoir_get_number(e, "Cam", "gain_e_per_adu", &x));
  CHECK(x == 1.0); /* unchanged by the refused values */

  /* The spec's frame (noise off: deterministic), and no ADU image. */
  OK(eoir_set_bool(e, "Cam", "noise_enabled", 0));
  FAILS(eoir_image_get_adu(e, "Cam", adu, N), EOIR_ERR_NO_STATE, "Cam");
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, spec_e, N));
  FAILS(eoir_image_get_adu(e, "Cam", adu, N), EOIR_ERR_NO_STATE, "detector_model");
  FAILS(eoir_image_get(e, "Cam", EOIR_IMAGE_SENSOR_ADU, adu_d, N), EOIR_ERR_NO_STATE, "detector_model");
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  OK(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, &info));
  CHECK(info.gain_e_per_adu == 0.0 && info.saturation_adu == 0.0 && info.adc_max_adu == 0.0);

  /* The stage on, noise on: the properties round-trip. */
  OK(eoir_set_bool(e, "Cam", "detector_model", 1));
  OK(eoir_set_bool(e, "Cam", "noise_enabled", 1));
  OK(eoir_set_number(e, "Cam", "gain_e_per_adu", 2.0));
  OK(eoir_set_number(e, "Cam", "bias_adu", 300.0));
  OK(eoir_set_number(e, "Cam", "read_noise_e", 5.0));
  OK(eoir_set_number(e, "Cam", "dark_current_e_s", 100.0));
  OK(eoir_set_number(e, "Cam", "full_well_e", 20000.0));
  OK(eoir_set_integer(e, "Cam", "adc_bits", 14));
  OK(eoir_set_number(e, "Cam", "prnu_fraction", 0.01));
  OK(eoir_set_number(e, "Cam", "dsnu_e_s", 5.0));
  OK(eoir_set_number(e, "Cam", "hot_pixel_fraction", 0.01));
  OK(eoir_set_number(e, "Cam", "dead_pixel_fraction", 0.01));
  OK(eoir_set_integer(e, "Cam", "detector_pattern_seed", 42));
  OK(eoir_get_integer(e, "Cam", "adc_bits", &bits));
  CHECK(bits == 14);
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, el, N));
  OK(eoir_image_get_adu(e, "Cam", adu, N));
  OK(eoir_image_get(e, "Cam", EOIR_IMAGE_SENSOR_ADU, adu_d, N));
  FAILS(eoir_image_get_adu(e, "Cam", small, 4), EOIR_ERR_BUFFER_TOO_SMALL, "capacity");
  FAILS(eoir_image_get_adu(e, "Cam", NULL, N), EOIR_ERR_NULL_ARGUMENT, "adu");
  for (i = 0; i < N; ++i) {
    /* ADU = clamp(floor(e / 2 + 300 + 1/2), 0, 2^14 - 1); full well 20000 e- plus read noise (< 10 sigma). */
    double a = floor(el[i] / 2.0 + 300.0 + 0.5);
    a = a < 0 ? 0 : a > 16383 ? 16383 : a;
    consistent = consistent && (double)adu[i] == a && adu_d[i] == (double)adu[i];
    within = within && isfinite(el[i]) && el[i] <= 20000.0 + 50.0;
  }
  CHECK(consistent);
  CHECK(within);
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  OK(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SENSOR_ADU, &info));
  CHECK(info.width == 16 && info.height == 16 && info.kind == EOIR_IMAGE_SENSOR_ADU);
  CHECK(strcmp(info.unit, "adu") == 0);
  CHECK(info.gain_e_per_adu == 2.0 && info.bias_adu == 300.0);
  CHECK(info.saturation_electrons == 20000.0 && info.read_noise_electrons == 5.0);
  CHECK(info.saturation_adu == 10300.0); /* floor(20000 / 2 + 300 + 1/2) */
  CHECK(info.adc_max_adu == 16383.0);

  /* Noise off: whole ADU of the mean, and the stage off again gives the spec's frame bit for bit. */
  OK(eoir_set_bool(e, "Cam", "noise_enabled", 0));
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_get_adu(e, "Cam", adu, N));
  for (i = 0; i < N; ++i) whole = whole && adu[i] >= 300 && adu[i] <= 16383;
  CHECK(whole);
  OK(eoir_set_bool(e, "Cam", "detector_model", 0));
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, spec_e2, N));
  for (i = 0; i < N; ++i) same = same && spec_e[i] == spec_e2[i];
  CHECK(same);
  FAILS(eoir_image_get_adu(e, "Cam", adu, N), EOIR_ERR_NO_STATE, "detector_model");

  /* Saved and restored with the state. */
  OK(eoir_set_bool(e, "Cam", "detector_model", 1));
  CHECK(mkdtemp(dir) != NULL);
  snprintf(path, sizeof path, "%s/detector.scd", dir);
  OK(eoir_state_save(e, path));
  OK(eoir_engine_create(NULL, &e2));
  OK(eoir_state_load(e2, path));
  OK(eoir_get_bool(e2, "Cam", "detector_model", &on));
  CHECK(on == 1);
  OK(eoir_get_number(e2, "Cam", "gain_e_per_adu", &x));
  CHECK(x == 2.0);
  OK(eoir_get_number(e2, "Cam", "dsnu_e_s", &x));
  CHECK(x == 5.0);
  OK(eoir_get_number(e2, "Cam", "hot_pixel_fraction", &x));
  CHECK(x == 0.01);
  OK(eoir_get_integer(e2, "Cam", "adc_bits", &bits));
  CHECK(bits == 14);
  OK(eoir_get_integer(e2, "Cam", "detector_pattern_seed", &bits));
  CHECK(bits == 42);
  unlink(path);
  rmdir(dir);

  /* The plugin table carries the call. */
  OK(eoir_plugin_entry(1, NULL, &table));
  api = (const eoir_api_v1*)table;
  CHECK(api->struct_size >= offsetof(eoir_api_v1, image_get_adu) + sizeof api->image_get_adu);
  OK(eoir_render(e, "Cam"));
  OK(api->image_get_adu(e, "Cam", adu, N));

  eoir_engine_destroy(e2);
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
