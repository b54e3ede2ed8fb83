/*
 * example_host.c — the thin C99 example host.
 *
 * Loads the engine as a plugin (plugin_loader.h), builds the spec 7.6
 * Valid_Sens_StaticMetrics scenario through the C ABI only, steps the time and
 * prints every static metric as "Group | Element | value | unit" (%.6g).
 * Curves print as "curve(N points)" in the value column.
 *
 * Usage: eoir_example_host [LIBRARY]   (else EOIR_LIBRARY, else the build's)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plugin_loader.h"

static const eoir_api_v1* api;

static void host_log(void* user, int32_t level, const char* message) {
  static const char* const names[] = {"debug", "info", "warning", "error"};
  (void)user;
  fprintf(stderr, "[engine %s] %s\n", (level >= 0 && level <= 3) ? names[level] : "log", message);
}

static int32_t host_progress(void* user, double fraction, const char* what) {
  (void)user;
  (void)fraction;
  (void)what;
  return 0; /* never cancel */
}

/* Prints the engine's message and returns 1 if status is an error. */
static int failed(eoir_status status, const char* what) {
  if (status == EOIR_OK) return 0;
  fprintf(stderr, "eoir_example_host: %s: %s (%s)\n", what, api->last_error(), api->status_name(status));
  return 1;
}

#define CHECK(call, what) \
  do {                    \
    if (failed((call), (what))) goto fail; \
  } while (0)

int main(int argc, char** argv) {
  eoir_loader_plugin plugin;
  eoir_host_api host;
  char message[EOIR_LOADER_MESSAGE_MAX];
  eoir_engine engine = NULL;
  eoir_time time;
  eoir_state state;
  size_t g, e, step;
  const char* group;
  const double sensitivity[2] = {10.0, 1e-18};
  const double saturation[2] = {10.0, 1e-15};
  const char* const sensor = "Sensor1";
  int rc = 1;

  memset(&host, 0, sizeof host);
  host.struct_size = sizeof host;
  host.log = host_log;
  host.progress = host_progress;
  if (eoir_loader_open(argc > 1 ? argv[1] : NULL, EOIR_VERSION_MAJOR, &host, &plugin, message,
                       sizeof message) != EOIR_OK) {
    fprintf(stderr, "eoir_example_host: %s\n", message);
    return 1;
  }
  api = plugin.api;

  CHECK(api->engine_create(NULL, &engine), "engine_create");
  CHECK(api->object_add(engine, EOIR_KIND_SATELLITE, "Satellite1"), "object_add Satellite1");
  CHECK(api->sensor_add(engine, sensor, "Satellite1"), "sensor_add Sensor1");

  /* Spec 7.6 Table 3 sensor, set explicitly. */
  CHECK(api->set_integer(engine, sensor, "horizontal_pixels", 128), "horizontal_pixels");
  CHECK(api->set_integer(engine, sensor, "vertical_pixels", 128), "vertical_pixels");
  CHECK(api->set_number(engine, sensor, "horizontal_fov_deg", 0.5), "horizontal_fov_deg");
  CHECK(api->set_number(engine, sensor, "vertical_fov_deg", 0.5), "vertical_fov_deg");
  CHECK(api->set_number(engine, sensor, "band_low_um", 1.0), "band_low_um");
  CHECK(api->set_number(engine, sensor, "band_high_um", 4.0), "band_high_um");
  CHECK(api->set_number(engine, sensor, "f_number", 3.5), "f_number");
  CHECK(api->set_number(engine, sensor, "focal_length_cm", 147.0), "focal_length_cm");
  CHECK(api->set_number(engine, sensor, "defocus_mm", 0.0), "defocus_mm");
  CHECK(api->set_string(engine, sensor, "image_quality", "diffraction_limited"), "image_quality");
  CHECK(api->set_number(engine, sensor, "diffraction_wavelength_um", 2.5), "diffraction_wavelength_um");
  CHECK(api->set_number(engine, sensor, "integration_time_ms", 10.0), "integration_time_ms");
  CHECK(api->set_string(engine, sensor, "sensitivity_quantity", "irradiance"), "sensitivity_quantity");
  CHECK(api->set_array(engine, sensor, "sensitivity_pairs", sensitivity, 2), "sensitivity_pairs");
  CHECK(api->set_string(engine, sensor, "saturation_quantity", "irradiance"), "saturation_quantity");
  CHECK(api->set_array(engine, sensor, "saturation_pairs", saturation, 2), "saturation_pairs");
  CHECK(api->set_number(engine, sensor, "jitter_mrad", 0.0), "jitter_mrad");

  /* A GEO satellite over longitude 0 at the scenario start (J2000, metres). */
  CHECK(api->time_from_iso("2010-08-25T18:00:00Z", &time), "time_from_iso");
  CHECK(api->engine_set_time(engine, &time), "engine_set_time");
  memset(&state, 0, sizeof state);
  state.struct_size = sizeof state;
  state.frame = EOIR_FRAME_J2000;
  state.position[0] = 42164.17e3;
  state.velocity[1] = 3074.66;
  state.attitude[0] = 1.0;
  CHECK(api->object_set_state(engine, "Satellite1", NULL, &state), "object_set_state Satellite1");

  for (step = 0; step < 3; ++step) {
    time.jd2 += 60.0 / 86400.0;
    CHECK(api->engine_set_time(engine, &time), "engine_set_time");
  }

  for (g = 0; api->provider_group_at(g, &group) == EOIR_OK; ++g) {
    eoir_element_info info;
    if (strcmp(group, "EOIR Sensor-to-Target Metrics") == 0) continue; /* needs a target */
    for (e = 0;; ++e) {
      double value = 0.0;
      size_t count = 0;
      memset(&info, 0, sizeof info);
      info.struct_size = sizeof info;
      if (api->provider_element_at(group, e, &info) != EOIR_OK) break;
      if (info.type == EOIR_TYPE_CURVE) {
        if (api->provider_get_curve(engine, group, info.name, sensor, NULL, NULL, NULL, 0, &count) != EOIR_OK &&
            count == 0)
          continue; /* an element this host cannot evaluate */
        printf("%s | %s | curve(%lu points) | %s\n", group, info.name, (unsigned long)count, info.unit);
      } else {
        if (api->provider_get(engine, group, info.name, sensor, NULL, &value) != EOIR_OK) continue;
        printf("%s | %s | %.6g | %s\n", group, info.name, value, info.unit);
      }
    }
  }
  rc = 0;

fail:
  api->engine_destroy(engine);
  eoir_loader_close(&plugin);
  return rc;
}
