/* Adaptive fidelity through the C ABI (README "Adaptive fidelity"): the
 * sensor property error_budget is validated naming the field and saved with
 * the sensor; eoir_frame_fidelity_get reports the settings of the last frame
 * (the sensor's own with budget 0, the chosen ones with a budget) and the
 * plugin table carries it. */
#include "host_target_sensor.h"

/* The number after "\"key\":" in a JSON text, NAN if absent. */
static double json_number(const char* text, const char* key) {
  char pattern[64];
  const char* at;
  snprintf(pattern, sizeof pattern, "\"%s\":", key);
  at = strstr(text, pattern);
  return at ? strtod(at + strlen(pattern), NULL) : NAN;
}

int main(void) {
  eoir_engine e = NULL;
  const eoir_api_v1* api = NULL;
  const void* table = NULL;
  char text[4096], small[8];
  size_t length = 0, length2 = 0;
  double budget = -1;
  double before[16 * 16], after[16 * 16];
  int i, same = 1;

  OK(eoir_engine_create(NULL, &e));
  add_host_target_sensor(e, "Sensor1");

  /* Bad budgets are refused, naming the field. */
  FAILS(eoir_set_number(e, "Sensor1", "error_budget", NAN), EOIR_ERR_OUT_OF_RANGE, "error_budget");
  FAILS(eoir_set_number(e, "Sensor1", "error_budget", -0.01), EOIR_ERR_OUT_OF_RANGE, "error_budget");
  FAILS(eoir_set_number(e, "Sensor1", "error_budget", 1.0), EOIR_ERR_OUT_OF_RANGE, "error_budget");
  FAILS(eoir_frame_fidelity_get(e, "Sensor1", text, sizeof text, &length), EOIR_ERR_NO_STATE, "sensor");

  /* Budget 0 (the default): the sensor's own settings, estimated error 0. */
  OK(eoir_get_number(e, "Sensor1", "error_budget", &budget));
  CHECK(budget == 0.0);
  OK(eoir_render(e, "Sensor1"));
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SENSOR_MEAN, before, 16 * 16));
  OK(eoir_frame_fidelity_get(e, "Sensor1", NULL, 0, &length));
  CHECK(length > 0 && length < sizeof text);
  OK(eoir_frame_fidelity_get(e, "Sensor1", text, sizeof text, &length2));
  CHECK(length2 == length && strlen(text) == length);
  CHECK(json_number(text, "error_budget") == 0.0);
  CHECK(json_number(text, "estimated_error") == 0.0);
  CHECK(json_number(text, "samples_per_pixel") == 4.0);
  CHECK(json_number(text, "spectral_intervals") == 10.0);
  CHECK(strstr(text, "\"scene_mode\":\"coarse\"") != NULL);
  FAILS(eoir_frame_fidelity_get(e, "Sensor1", small, sizeof small, &length2), EOIR_ERR_BUFFER_TOO_SMALL, "capacity");

  /* A budget: the frame reports it, and an estimate within it. */
  OK(eoir_set_number(e, "Sensor1", "error_budget", 0.005));
  OK(eoir_render(e, "Sensor1"));
  OK(eoir_frame_fidelity_get(e, "Sensor1", text, sizeof text, &length));
  CHECK(json_number(text, "error_budget") == 0.005);
  CHECK(json_number(text, "estimated_error") >= 0.0 && json_number(text, "estimated_error") <= 0.005);
  CHECK(json_number(text, "samples_per_pixel") >= 1.0 && json_number(text, "samples_per_pixel") <= 16.0);

  /* Back to 0: the frame is the one rendered before, bit for bit. */
  OK(eoir_set_number(e, "Sensor1", "error_budget", 0.0));
  OK(eoir_render(e, "Sensor1"));
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SENSOR_MEAN, after, 16 * 16));
  for (i = 0; i < 16 * 16; ++i) same = same && before[i] == after[i];
  CHECK(same);

  /* The plugin table carries the function. */
  OK(eoir_plugin_entry(1, NULL, &table));
  api = (const eoir_api_v1*)table;
  CHECK(api->struct_size >= offsetof(eoir_api_v1, frame_fidelity_get) + sizeof api->frame_fidelity_get);
  OK(api->frame_fidelity_get(e, "Sensor1", text, sizeof text, &length));
  CHECK(json_number(text, "error_budget") == 0.0);

  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
