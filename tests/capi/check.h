/* A minimal C99 test harness for the C ABI tests. */
#ifndef EOIR_TEST_CHECK_H
#define EOIR_TEST_CHECK_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eoir/eoir.h"

static int check_failures = 0;
static int check_count = 0;

#define CHECK(cond)                                                              \
  do {                                                                           \
    ++check_count;                                                               \
    if (!(cond)) {                                                               \
      ++check_failures;                                                          \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);  \
    }                                                                            \
  } while (0)

/* Calls must succeed. */
#define OK(call)                                                                              \
  do {                                                                                        \
    eoir_status st_ = (call);                                                                 \
    ++check_count;                                                                            \
    if (st_ != EOIR_OK) {                                                                     \
      ++check_failures;                                                                       \
      fprintf(stderr, "%s:%d: %s -> %s: %s\n", __FILE__, __LINE__, #call, eoir_status_name(st_), \
              eoir_last_error());                                                             \
    }                                                                                         \
  } while (0)

/* Calls must fail with `status` and a message containing `field`. */
#define FAILS(call, status, field)                                                                 \
  do {                                                                                             \
    eoir_status st_ = (call);                                                                      \
    ++check_count;                                                                                 \
    if (st_ != (status) || strstr(eoir_last_error(), (field)) == NULL) {                           \
      ++check_failures;                                                                            \
      fprintf(stderr, "%s:%d: %s -> %s (\"%s\"), expected %s naming \"%s\"\n", __FILE__, __LINE__, \
              #call, eoir_status_name(st_), eoir_last_error(), eoir_status_name(status), (field));  \
    }                                                                                              \
  } while (0)

/* |actual - expected| <= rel * |expected| */
#define NEAR_REL(actual, expected, rel)                                                          \
  do {                                                                                           \
    double a_ = (actual), e_ = (expected);                                                       \
    ++check_count;                                                                               \
    if (!(fabs(a_ - e_) <= (rel) * fabs(e_))) {                                                  \
      ++check_failures;                                                                          \
      fprintf(stderr, "%s:%d: %s = %.9g, expected %.9g within %g relative\n", __FILE__, __LINE__, \
              #actual, a_, e_, (double)(rel));                                                   \
    }                                                                                            \
  } while (0)

/* Writes text to a new file; exits the test if it cannot. */
static inline void write_text(const char* path, const char* text) {
  FILE* f = fopen(path, "wb");
  if (f == NULL) {
    perror(path);
    exit(2);
  }
  fputs(text, f);
  fclose(f);
}

/* A state at rest at (x, y, z) of `frame`, identity attitude. */
static inline eoir_state state_at(int32_t frame, double x, double y, double z) {
  eoir_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.frame = frame;
  s.position[0] = x;
  s.position[1] = y;
  s.position[2] = z;
  s.attitude[0] = 1;
  return s;
}

/* Pushes a J2000 state at rest, identity attitude. */
static inline eoir_status put_j2000(eoir_engine e, const char* name, double x, double y, double z) {
  const eoir_state s = state_at(EOIR_FRAME_J2000, x, y, z);
  return eoir_object_set_state(e, name, NULL, &s);
}

/* A satellite "Host" (shape none) carrying the sensor "Cam": pixels x pixels,
 * band low-high um, noise off; the engine's time set to `iso`. */
static inline void host_camera(eoir_engine e, const char* iso, int64_t pixels, double band_low_um,
                               double band_high_um) {
  eoir_time t;
  OK(eoir_time_from_iso(iso, &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Host"));
  OK(eoir_set_string(e, "Host", "shape", "none"));
  OK(eoir_sensor_add(e, "Cam", "Host"));
  OK(eoir_set_integer(e, "Cam", "horizontal_pixels", pixels));
  OK(eoir_set_integer(e, "Cam", "vertical_pixels", pixels));
  OK(eoir_set_number(e, "Cam", "band_low_um", band_low_um));
  OK(eoir_set_number(e, "Cam", "band_high_um", band_high_um));
  OK(eoir_set_bool(e, "Cam", "noise_enabled", 0));
}

/* The Earth-fixed position at distance L from the point (0 N, 0 E, height
 * h) toward the north at elevation el_deg (atmosphere tests). */
static inline eoir_status place_north(eoir_engine e, const char* name, double h, double L, double el_deg) {
  const double el = el_deg * 3.14159265358979323846 / 180.0;
  const eoir_state s = state_at(EOIR_FRAME_EARTH_FIXED, 6378137.0 + h + L * sin(el), 0.0, L * cos(el));
  return eoir_object_set_state(e, name, NULL, &s);
}

/* Kasten and Young (1989), Applied Optics 28, 4735: the relative air mass
 * at apparent zenith angle z (deg). */
static inline double kasten_young(double z_deg) {
  return 1.0 / (cos(z_deg * 3.14159265358979323846 / 180.0) + 0.50572 * pow(96.07995 - z_deg, -1.6364));
}

/* |actual - expected| <= tol */
#define NEAR_ABS(actual, expected, tol)                                                          \
  do {                                                                                           \
    double a_ = (actual), e_ = (expected);                                                       \
    ++check_count;                                                                               \
    if (!(fabs(a_ - e_) <= (tol))) {                                                             \
      ++check_failures;                                                                          \
      fprintf(stderr, "%s:%d: %s = %.12g, expected %.12g within %g\n", __FILE__, __LINE__, #actual, \
              a_, e_, (double)(tol));                                                            \
    }                                                                                            \
  } while (0)

#define CHECK_SUMMARY()                                                                  \
  (printf("%d checks, %d failed\n", check_count, check_failures), check_failures ? 1 : 0)

#endif
