/* The host's callbacks (eoir_host_api, eoir_plugin_entry): engines report
 * progress during renders and series of data providers, log a line per
 * render, and stop with EOIR_ERR_CANCELLED when progress returns non-zero,
 * keeping the previous frame. */
#include "host_target_sensor.h"

struct host_record {
  int progress_calls;
  int log_calls;
  double last_fraction;
  int monotonic;
  int cancel_after;  /* cancel from this call on (0: never) */
};

static int32_t on_progress(void* user, double fraction, const char* what) {
  struct host_record* r = (struct host_record*)user;
  ++r->progress_calls;
  if (fraction < r->last_fraction) r->monotonic = 0;
  r->last_fraction = fraction;
  (void)what;
  return r->cancel_after > 0 && r->progress_calls >= r->cancel_after;
}

static void on_log(void* user, int32_t level, const char* message) {
  struct host_record* r = (struct host_record*)user;
  ++r->log_calls;
  CHECK(level >= 0 && level <= 3);
  CHECK(message != NULL && strstr(message, "render") != NULL);
}

int main(void) {
  struct host_record record = {0, 0, 0.0, 1, 0};
  eoir_host_api host;
  const void* table = NULL;
  eoir_engine e = NULL;
  eoir_time t, times[3];
  double before[16 * 16], after[16 * 16], values[3];
  int i, same = 1;

  memset(&host, 0, sizeof host);
  host.struct_size = sizeof host;
  host.user = &record;
  host.progress = on_progress;
  host.log = on_log;
  OK(eoir_plugin_entry(1, &host, &table));
  CHECK(table != NULL);

  OK(eoir_engine_create(NULL, &e));
  add_host_target_sensor(e, "Sensor1");
  OK(eoir_engine_get_time(e, EOIR_TIME_UTC, &t));

  OK(eoir_render(e, "Sensor1"));
  CHECK(record.progress_calls >= 3);
  CHECK(record.monotonic);
  CHECK(record.last_fraction == 1.0);
  CHECK(record.log_calls == 1);
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SENSOR_MEAN, before, 16 * 16));

  /* A series of a data provider reports progress too. */
  record.progress_calls = 0;
  record.last_fraction = 0;
  for (i = 0; i < 3; ++i) {
    times[i] = t;
    times[i].jd2 += i / 86400.0;
  }
  OK(eoir_provider_series(e, "EOIR Sensor-to-Target Metrics", "Range to Target", "Sensor1", "Target", times, 3,
                          values));
  CHECK(record.progress_calls >= 2);
  NEAR_REL(values[0], 50.0, 1e-9);

  /* Cancel the next render after its first report: the old frame stays. */
  record.progress_calls = 0;
  record.last_fraction = 0;
  record.cancel_after = 2;
  OK(eoir_set_number(e, "Target", "temperature_K", 500.0));
  FAILS(eoir_render(e, "Sensor1"), EOIR_ERR_CANCELLED, "cancelled");
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SENSOR_MEAN, after, 16 * 16));
  for (i = 0; i < 16 * 16; ++i) same = same && before[i] == after[i];
  CHECK(same);
  CHECK(strcmp(eoir_status_name(EOIR_ERR_CANCELLED), "EOIR_ERR_CANCELLED") == 0);

  eoir_engine_destroy(e);
  OK(eoir_plugin_entry(1, NULL, &table)); /* clears the callbacks */
  return CHECK_SUMMARY();
}
