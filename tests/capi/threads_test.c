/* C ABI threads contract (eoir.h "Threads"): calls on one engine from two
 * threads are serialized and never corrupt it (a render racing with property
 * changes, providers and state queries); two engines on two threads run in
 * parallel and give the same frames as when run alone. Run under ASan in CI
 * (before the per-engine lock, the first case was a heap-use-after-free). */
#include <pthread.h>
#include <stdlib.h>

#include "table3_sensor.h"

enum { ROUNDS = 40 };

static eoir_engine make_engine(void) {
  eoir_engine e = NULL;
  eoir_time t;
  eoir_state s;
  const double here[3] = {7000e3, 0, 0}, target[3] = {7000e3, 0, 50e3};
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T18:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Host"));
  OK(eoir_set_string(e, "Host", "shape", "none"));
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.attitude[0] = 1;
  memcpy(s.position, here, sizeof here);
  OK(eoir_object_set_state(e, "Host", NULL, &s));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Target"));
  memcpy(s.position, target, sizeof target);
  OK(eoir_object_set_state(e, "Target", NULL, &s));
  add_table3_sensor(e, "Host", "Sensor1");
  OK(eoir_set_integer(e, "Sensor1", "horizontal_pixels", 32));
  OK(eoir_set_integer(e, "Sensor1", "vertical_pixels", 32));
  OK(eoir_set_bool(e, "Sensor1", "noise_enabled", 0));
  return e;
}

static void* render_loop(void* arg) {
  eoir_engine e = (eoir_engine)arg;
  int i;
  for (i = 0; i < ROUNDS; ++i) {
    double snr = 0;
    if (eoir_render(e, "Sensor1") != EOIR_OK) return (void*)1;
    if (eoir_snr_constraint(e, "Sensor1", "Target", NULL, &snr) != EOIR_OK || !(snr >= 0)) return (void*)1;
  }
  return NULL;
}

static void* change_loop(void* arg) {
  eoir_engine e = (eoir_engine)arg;
  int i;
  for (i = 0; i < ROUNDS; ++i) {
    double v = 0;
    if (eoir_set_number(e, "Target", "temperature_K", 280.0 + i) != EOIR_OK) return (void*)1;
    if (eoir_set_number(e, "Sensor1", "integration_time_ms", 5.0 + i % 7) != EOIR_OK) return (void*)1;
    if (eoir_provider_get(e, "EOIR Sensor Optics", "Ensquared Energy", "Sensor1", NULL, &v) != EOIR_OK) return (void*)1;
    if (!(v > 0.9)) return (void*)1;
  }
  return NULL;
}

/* The sum of the noise-free image of an engine's last frame. */
static double image_sum(eoir_engine e) {
  double image[32 * 32], sum = 0;
  int i;
  OK(eoir_image_get(e, "Sensor1", EOIR_IMAGE_SENSOR_MEAN, image, 32 * 32));
  for (i = 0; i < 32 * 32; ++i) sum += image[i];
  return sum;
}

static void* render_once(void* arg) {
  return eoir_render((eoir_engine)arg, "Sensor1") == EOIR_OK ? NULL : (void*)1;
}

int main(void) {
  pthread_t a, b;
  void* ra = NULL;
  void* rb = NULL;
  eoir_engine shared = make_engine(), first = make_engine(), second = make_engine();
  double alone;

  /* One engine, two threads: every call succeeds. */
  CHECK(pthread_create(&a, NULL, render_loop, shared) == 0);
  CHECK(pthread_create(&b, NULL, change_loop, shared) == 0);
  pthread_join(a, &ra);
  pthread_join(b, &rb);
  CHECK(ra == NULL);
  CHECK(rb == NULL);
  OK(eoir_render(shared, "Sensor1"));

  /* Two engines, two threads: each frame equals the one rendered alone. */
  OK(eoir_render(first, "Sensor1"));
  alone = image_sum(first);
  CHECK(alone > 0);
  CHECK(pthread_create(&a, NULL, render_once, first) == 0);
  CHECK(pthread_create(&b, NULL, render_once, second) == 0);
  pthread_join(a, &ra);
  pthread_join(b, &rb);
  CHECK(ra == NULL && rb == NULL);
  CHECK(image_sum(first) == alone);
  CHECK(image_sum(second) == alone);

  eoir_engine_destroy(shared);
  eoir_engine_destroy(first);
  eoir_engine_destroy(second);
  return CHECK_SUMMARY();
}
