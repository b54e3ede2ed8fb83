/* C ABI: bad input gets a status and a message naming the field, and no call
 * returns non-finite data with EOIR_OK (issue 11, item 8; DESIGN 5).
 *
 * Every numeric, integer and array property of every kind (sensor,
 * satellite, aircraft, ground vehicle, missile, the Earth, the star field,
 * a site whose sensor tracks the target),
 * as eoir_property_info lists it, is set to extreme values: just outside each
 * bound of its range, NaN, +-Inf, +-1e308, +-DBL_MAX, +-5e-324 must be
 * refused with EOIR_ERR_OUT_OF_RANGE (or LIMIT_EXCEEDED, NOT_ALLOWED) and a
 * message naming the property; each bound, just inside an open bound, 0,
 * 5e-324 and 1 where in range are refused with a documented status and a
 * message, or accepted. After each accepted value the frame is rendered and
 * every image kind, the truth, a pick, the SNR constraint, the target
 * spectrum and every data provider are read: each call either fails with a
 * status and a message or returns finite values. Properties that only change
 * the cost of a frame (pixel counts, grid sizes) are read through the static
 * data providers only at their costly end.
 *
 * Then the same for: booleans other than 0 and 1; arrays and series of 2^60
 * values; pushed states (positions, speeds, attitudes, rates, geodetic
 * coordinates) at the extremes; engine times at and beyond the accepted
 * dates (the engine stays able to save and load); composite parts at the
 * extremes; tabulated spectra; object names that are not valid UTF-8. */
#define _POSIX_C_SOURCE 200809L
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

#include "check.h"

#ifndef EXTREMES_SCD
#define EXTREMES_SCD "capi_extremes_test.scd"
#endif

static int checked_values = 0;
static const char* target = "Target";

/* A status is acceptable if it is OK or a documented error with a message;
 * EOIR_ERR_INTERNAL is a bug. */
static int call_ok(eoir_status st, const char* what, const char* label) {
  ++check_count;
  if (st == EOIR_OK) return 1;
  if (getenv("EOIR_TEST_VERBOSE")) printf("%s: %s -> %s: %s\n", label, what, eoir_status_name(st), eoir_last_error());
  if (st == EOIR_ERR_INTERNAL || eoir_last_error()[0] == '\0') {
    ++check_failures;
    fprintf(stderr, "%s: %s -> %s (\"%s\")\n", label, what, eoir_status_name(st), eoir_last_error());
  }
  return 0;
}

/* Out-of-range input: refused, naming `field`. */
static void refused(eoir_status st, const char* field, const char* label) {
  ++check_count;
  if ((st != EOIR_ERR_OUT_OF_RANGE && st != EOIR_ERR_LIMIT_EXCEEDED && st != EOIR_ERR_NOT_ALLOWED) ||
      strstr(eoir_last_error(), field) == NULL) {
    ++check_failures;
    fprintf(stderr, "%s: expected a refusal naming '%s', got %s (\"%s\")\n", label, field, eoir_status_name(st),
            st == EOIR_OK ? "" : eoir_last_error());
  }
}

static void must_be_finite(double v, const char* what, const char* label) {
  ++check_count;
  ++checked_values;
  if (!isfinite(v)) {
    ++check_failures;
    fprintf(stderr, "%s: %s = %g with EOIR_OK\n", label, what, v);
  }
}

/* Every data provider of Sensor1, without and with the target. */
static void read_providers(eoir_engine e, const char* label) {
  const char* group = NULL;
  size_t g, i;
  for (g = 0; eoir_provider_group_at(g, &group) == EOIR_OK; ++g) {
    eoir_element_info info;
    memset(&info, 0, sizeof info);
    info.struct_size = sizeof info;
    for (i = 0; eoir_provider_element_at(group, i, &info) == EOIR_OK; ++i) {
      char what[256];
      int t;
      snprintf(what, sizeof what, "%s / %s", group, info.name);
      for (t = 0; t < 2; ++t) {
        const char* with = t ? target : NULL;
        if (info.type == EOIR_TYPE_CURVE) {
          size_t n = 0, k;
          double *x, *y;
          if (!call_ok(eoir_provider_get_curve(e, group, info.name, "Sensor1", with, NULL, NULL, 0, &n), what, label))
            continue;
          x = (double*)calloc(n ? n : 1, sizeof *x);
          y = (double*)calloc(n ? n : 1, sizeof *y);
          if (call_ok(eoir_provider_get_curve(e, group, info.name, "Sensor1", with, x, y, n, &n), what, label))
            for (k = 0; k < n; ++k) {
              must_be_finite(x[k], what, label);
              must_be_finite(y[k], what, label);
            }
          free(x);
          free(y);
        } else {
          double v = 0;
          if (call_ok(eoir_provider_get(e, group, info.name, "Sensor1", with, &v), what, label))
            must_be_finite(v, what, label);
        }
      }
    }
  }
}

static void read_image(eoir_engine e, int32_t kind, const char* label) {
  eoir_image_info info;
  size_t n, i;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  if (!call_ok(eoir_image_info_get(e, "Sensor1", kind, &info), "image_info_get", label)) return;
  must_be_finite(info.boresight_ra_deg + info.boresight_dec_deg + info.up_ra_deg + info.up_dec_deg,
                 "image_info angles", label);
  must_be_finite(info.time_jd_utc[0] + info.time_jd_utc[1], "image_info time", label);
  /* 1.6: the integration, the astrometric WCS, the observer */
  must_be_finite(info.start_jd_utc[0] + info.start_jd_utc[1] + info.end_jd_utc[0] + info.end_jd_utc[1],
                 "image_info start and end", label);
  must_be_finite(info.astrometric_ra_deg + info.astrometric_dec_deg + info.astrometric_cd_deg[0] +
                     info.astrometric_cd_deg[1] + info.astrometric_cd_deg[2] + info.astrometric_cd_deg[3],
                 "image_info astrometric WCS", label);
  CHECK(info.astrometric_cd_deg[0] * info.astrometric_cd_deg[3] - info.astrometric_cd_deg[1] * info.astrometric_cd_deg[2] != 0);
  must_be_finite(info.observer_earth_fixed_m[0] + info.observer_earth_fixed_m[1] + info.observer_earth_fixed_m[2] +
                     info.saturation_electrons + info.read_noise_electrons,
                 "image_info observer and detector", label);
  n = (size_t)info.width * info.height;
  CHECK(n > 0);
  if (kind == EOIR_IMAGE_SCENE_DISPLAY || kind == EOIR_IMAGE_SENSOR_DISPLAY) {
    uint8_t* b = (uint8_t*)malloc(n);
    call_ok(eoir_image_get_bytes(e, "Sensor1", kind, b, n), "image_get_bytes", label);
    free(b);
  } else {
    double* v = (double*)malloc(n * sizeof *v);
    if (call_ok(eoir_image_get(e, "Sensor1", kind, v, n), "image_get", label))
      for (i = 0; i < n; ++i) must_be_finite(v[i], "image", label);
    free(v);
  }
}

static void read_truth_and_pick(eoir_engine e, const char* label) {
  size_t count = 0, i;
  int32_t space;
  if (call_ok(eoir_truth_count(e, "Sensor1", &count), "truth_count", label))
    for (i = 0; i < count; ++i) {
      eoir_truth t;
      memset(&t, 0, sizeof t);
      t.struct_size = sizeof t;
      if (!call_ok(eoir_truth_get(e, "Sensor1", i, &t), "truth_get", label)) continue;
      must_be_finite(t.pixel_x + t.pixel_y, "truth pixel", label);
      must_be_finite(t.range_m, "truth.range_m", label);
      must_be_finite(t.effective_irradiance + t.effective_radiance, "truth radiometry", label);
      must_be_finite(t.snr, "truth.snr", label);
      must_be_finite(t.azimuth_deg + t.elevation_deg, "truth azimuth/elevation", label);
      must_be_finite(t.astrometric_ra_deg + t.astrometric_dec_deg + t.start_astrometric_ra_deg +
                         t.start_astrometric_dec_deg + t.end_astrometric_ra_deg + t.end_astrometric_dec_deg +
                         t.geometric_ra_deg + t.geometric_dec_deg,
                     "truth astrometric and geometric RA/Dec", label);
    }
  for (space = 0; space < 2; ++space) {
    static double wl[4096], l[4096];
    eoir_pick p;
    size_t n = 0;
    memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    if (!call_ok(eoir_pick_get(e, "Sensor1", space, 0, 0, &p, wl, l, 4096, &n), "pick_get", label)) continue;
    must_be_finite(p.range_m, "pick.range_m", label);
    must_be_finite(p.effective_radiance, "pick.effective_radiance", label);
    must_be_finite(p.temperature_K, "pick.temperature_K", label);
    must_be_finite(p.right_ascension_deg + p.declination_deg, "pick RA/Dec", label);
    for (i = 0; i < n && i < 4096; ++i) must_be_finite(wl[i] + l[i], "pick spectrum", label);
  }
}

/* Renders Sensor1 and reads every image kind, the truth, a pick, the SNR
 * constraint and the target spectrum. */
static void render_and_read(eoir_engine e, const char* label) {
  int32_t kind;
  size_t i, n = 0;
  double snr = 0;
  static double wl[4096], irr[4096];
  if (!call_ok(eoir_render(e, "Sensor1"), "render", label)) return;
  for (kind = EOIR_IMAGE_SCENE_RADIANCE; kind <= EOIR_IMAGE_SENSOR_DISPLAY; ++kind) read_image(e, kind, label);
  read_truth_and_pick(e, label);
  if (call_ok(eoir_snr_constraint(e, "Sensor1", target, NULL, &snr), "snr_constraint", label))
    must_be_finite(snr, "snr_constraint", label);
  if (call_ok(eoir_target_spectrum_get(e, "Sensor1", target, wl, irr, 4096, &n), "target_spectrum_get", label))
    for (i = 0; i < n && i < 4096; ++i) must_be_finite(wl[i] + irr[i], "target spectrum", label);
}

static void everything(eoir_engine e, const char* label) {
  render_and_read(e, label);
  read_providers(e, label);
}

/* A small frame. Space: Sensor1 on Satellite1 (7000 km on J2000 x) looks
 * along +z, away from the Earth, at the target 1000 km away, a 10 m sphere at
 * 300 K. Earth: Sensor1 at 7000 km on -z looks at the Earth's centre past the
 * target 100 km away. */
enum view { space, earth };

static eoir_engine scene(int32_t target_kind, enum view view, int stars) {
  eoir_engine e = NULL;
  const double r = 10.0;
  const double z = view == earth ? -7000e3 : 0.0;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  if (stars) OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite1"));
  OK(eoir_object_add(e, target_kind, target));
  OK(eoir_sensor_add(e, "Sensor1", "Satellite1"));
  OK(put_j2000(e, "Satellite1", view == earth ? 0.0 : 7000e3, 0, z));
  OK(put_j2000(e, target, view == earth ? 0.0 : 7000e3, view == earth ? 2e3 : 0.0, view == earth ? z + 100e3 : 1000e3));
  OK(eoir_set_array(e, target, "dimensions_m", &r, 1));
  OK(eoir_set_integer(e, "Sensor1", "horizontal_pixels", 8));
  OK(eoir_set_integer(e, "Sensor1", "vertical_pixels", 8));
  OK(eoir_set_number(e, "Sensor1", "horizontal_fov_deg", view == earth ? 2.0 : 0.01));
  OK(eoir_set_number(e, "Sensor1", "vertical_fov_deg", view == earth ? 2.0 : 0.01));
  return e;
}

/* Properties whose costly end (many pixels, intervals, samples, the largest
 * grids and tables) only changes the cost of a frame: the data providers
 * only, there. */
static int costly(const char* name, double value, double fallback) {
  static const char* const names[] = {
      "horizontal_pixels",     "vertical_pixels", "spectral_intervals",    "samples_per_pixel",
      "psf_grid_size",         "otf_table_size",  "temperature_table_size", "target_window_max_half_samples",
      "psf_fold_budget",       "otf_curve_points", NULL};
  int i;
  for (i = 0; names[i]; ++i)
    if (strcmp(names[i], name) == 0) return value > fallback;
  return 0;
}

static int in_range(const eoir_property_info* info, double x) {
  if (!isfinite(x)) return 0;
  if ((info->range_open & 1u) ? !(x > info->minimum) : !(x >= info->minimum)) return 0;
  if ((info->range_open & 2u) ? !(x < info->maximum) : !(x <= info->maximum)) return 0;
  return 1;
}

/* Sets `object`.`info->name` to x (every element of an array; a reference
 * pair's value at 1 ms), returns the status. */
static eoir_status set_value(eoir_engine e, const char* object, const eoir_property_info* info, double x,
                             size_t length) {
  if (info->type == EOIR_TYPE_INTEGER) {
    /* whole numbers as integers, others through eoir_set_number (refused) */
    if (!isfinite(x) || floor(x) != x || fabs(x) >= 9.2e18) return eoir_set_number(e, object, info->name, x);
    return eoir_set_integer(e, object, info->name, (int64_t)x);
  }
  if (info->type == EOIR_TYPE_ARRAY) {
    double a[3];
    size_t k;
    for (k = 0; k < 3; ++k) a[k] = x;
    if (strstr(info->name, "_pairs")) {
      a[0] = 1.0;
      length = 2;
    }
    return eoir_set_array(e, object, info->name, a, length > 3 ? 3 : length);
  }
  return eoir_set_number(e, object, info->name, x);
}

/* The value a property had, to go back to. */
typedef struct saved {
  double values[16];
  size_t count;
} saved;

static saved save_value(eoir_engine e, const char* object, const eoir_property_info* info) {
  saved s;
  s.count = 1;
  s.values[0] = 0;
  if (info->type == EOIR_TYPE_ARRAY) OK(eoir_get_array(e, object, info->name, s.values, 16, &s.count));
  else OK(eoir_get_number(e, object, info->name, &s.values[0]));
  return s;
}

static void restore_value(eoir_engine e, const char* object, const eoir_property_info* info, const saved* s) {
  if (info->type == EOIR_TYPE_ARRAY) OK(eoir_set_array(e, object, info->name, s->values, s->count));
  else if (info->type == EOIR_TYPE_INTEGER) OK(eoir_set_integer(e, object, info->name, (int64_t)s->values[0]));
  else OK(eoir_set_number(e, object, info->name, s->values[0]));
}

/* The extremes of one property of `object` in engine e. */
static void sweep_property(eoir_engine e, const char* object, const eoir_property_info* info) {
  const double tiny = DBL_MIN * DBL_EPSILON; /* 5e-324 */
  const saved original = save_value(e, object, info);
  const double fallback = original.count ? original.values[0] : 0.0;
  const size_t length = original.count;
  double values[24];
  size_t n = 0, k;
  eoir_status st;
  if (isfinite(info->minimum)) {
    values[n++] = info->minimum;
    values[n++] = nextafter(info->minimum, -HUGE_VAL);
    values[n++] = nextafter(info->minimum, HUGE_VAL);
    values[n++] = info->minimum - 1; /* integers */
  }
  if (isfinite(info->maximum)) {
    values[n++] = info->maximum;
    values[n++] = nextafter(info->maximum, HUGE_VAL);
    values[n++] = nextafter(info->maximum, -HUGE_VAL);
    values[n++] = info->maximum + 1;
  }
  values[n++] = NAN;
  values[n++] = HUGE_VAL;
  values[n++] = -HUGE_VAL;
  values[n++] = 1e308;
  values[n++] = -1e308;
  values[n++] = DBL_MAX;
  values[n++] = -DBL_MAX;
  values[n++] = tiny;
  values[n++] = -tiny;
  values[n++] = 0.0;
  values[n++] = 1.0;
  for (k = 0; k < n; ++k) {
    const double x = values[k];
    const int whole = info->type != EOIR_TYPE_INTEGER || (isfinite(x) && floor(x) == x);
    char label[200];
    snprintf(label, sizeof label, "%s.%s = %.17g", object, info->name, x);
    st = set_value(e, object, info, x, length);
    if (!in_range(info, x) || !whole) {
      refused(st, info->name, label);
      continue;
    }
    if (!call_ok(st, "set", label)) continue;
    if (costly(info->name, x, fallback)) read_providers(e, label);
    else everything(e, label);
    /* back to the default for the next value */
    restore_value(e, object, info, &original);
  }
  if (strstr(info->name, "_pairs")) {
    /* a pair's integration time at the extremes */
    static const double times[] = {0.0, -1.0, 1e-300, 1e308, NAN, HUGE_VAL};
    for (k = 0; k < sizeof times / sizeof times[0]; ++k) {
      const double pair[2] = {times[k], 1e-15};
      char label[200];
      snprintf(label, sizeof label, "%s.%s time = %g", object, info->name, times[k]);
      refused(eoir_set_array(e, object, info->name, pair, 2), info->name, label);
    }
  }
}

/* Sensor1 on the site Site1 (10 N, 20 E) tracking the target 1000 km
 * above it. */
static eoir_engine site_scene(void) {
  eoir_engine e = NULL;
  eoir_state s = state_at(EOIR_FRAME_GEODETIC, 10.0, 20.0, 1000e3);
  const double r = 10.0;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_SITE, "Site1"));
  OK(eoir_set_number(e, "Site1", "latitude_deg", 10.0));
  OK(eoir_set_number(e, "Site1", "longitude_deg", 20.0));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, target));
  OK(eoir_object_set_state(e, target, NULL, &s));
  OK(eoir_set_array(e, target, "dimensions_m", &r, 1));
  OK(eoir_sensor_add(e, "Sensor1", "Site1"));
  OK(eoir_set_integer(e, "Sensor1", "horizontal_pixels", 8));
  OK(eoir_set_integer(e, "Sensor1", "vertical_pixels", 8));
  OK(eoir_set_number(e, "Sensor1", "horizontal_fov_deg", 2.0));
  OK(eoir_set_number(e, "Sensor1", "vertical_fov_deg", 2.0));
  OK(eoir_sensor_point_at(e, "Sensor1", target));
  return e;
}

static void sweep(int32_t target_kind, const char* object, enum view view, int stars) {
  eoir_engine e = object && strcmp(object, "Site1") == 0 ? site_scene() : scene(target_kind, view, stars);
  size_t i;
  eoir_property_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  for (i = 0; eoir_property_info_at(e, object, i, &info) == EOIR_OK; ++i)
    if (info.type == EOIR_TYPE_NUMBER || info.type == EOIR_TYPE_INTEGER || info.type == EOIR_TYPE_ARRAY)
      sweep_property(e, object, &info);
    else if (info.type == EOIR_TYPE_BOOL) {
      refused(eoir_set_bool(e, object, info.name, 7), info.name, "bool 7");
      refused(eoir_set_bool(e, object, info.name, -1), info.name, "bool -1");
    }
  eoir_engine_destroy(e);
}

/* Arrays and series longer than the engine takes: refused, no allocation. */
static void huge_counts(void) {
  eoir_engine e = scene(EOIR_KIND_SATELLITE, space, 0);
  const double v[2] = {1.0, 1.0};
  eoir_time t[1];
  double out[1];
  const size_t huge = (size_t)1 << (sizeof(size_t) > 4 ? 60 : 31);
  refused(eoir_set_array(e, target, "dimensions_m", v, huge), "dimensions_m", "set_array 2^60");
  refused(eoir_set_array(e, target, "dimensions_m", v, (size_t)-1), "dimensions_m", "set_array SIZE_MAX");
  refused(eoir_set_array(e, "Sensor1", "sensitivity_pairs", v, huge), "sensitivity_pairs", "pairs 2^60");
  FAILS(eoir_set_array(e, target, "dimensions_m", NULL, 1), EOIR_ERR_NULL_ARGUMENT, "values");
  refused(eoir_spectrum_add(e, "s", v, v, huge), "count", "spectrum_add 2^60");
  OK(eoir_engine_get_time(e, EOIR_TIME_TT, &t[0]));
  refused(eoir_provider_series(e, "EOIR Sensor Optics", "F-number", "Sensor1", NULL, t, huge, out), "count",
          "provider_series 2^60");
  eoir_engine_destroy(e);
}

/* Tabulated spectra with NaN, negative or huge radiances, reversed or
 * repeated wavelengths: refused naming the field; extreme but valid ones
 * render finite. */
static void spectra(void) {
  eoir_engine e = scene(EOIR_KIND_SATELLITE, space, 0);
  const double wl[3] = {0.28, 10.0, 28.0}, reversed[3] = {28.0, 10.0, 0.28};
  const double nan_l[3] = {1, NAN, 1}, neg[3] = {1, -1, 1}, inf_l[3] = {1, HUGE_VAL, 1};
  const double big[3] = {1e300, 1e300, 1e300};
  eoir_status st;
  const double hottest[3] = {1e10, 1e10, 1e10};
  refused(eoir_spectrum_add(e, "s", wl, nan_l, 3), "s.value[1]", "spectrum NaN");
  refused(eoir_spectrum_add(e, "s", wl, neg, 3), "s: radiance_W_cm2_sr_um[1]", "spectrum negative");
  refused(eoir_spectrum_add(e, "s", wl, inf_l, 3), "s.value[1]", "spectrum inf");
  refused(eoir_spectrum_add(e, "s", wl, big, 3), "s: radiance_W_cm2_sr_um[0]", "spectrum 1e300");
  refused(eoir_spectrum_add(e, "s", reversed, hottest, 3), "s.wavelength_um", "spectrum reversed");
  st = eoir_spectrum_add(e, "s", wl, hottest, 3);
  if (call_ok(st, "spectrum_add 1e10", "spectrum 1e10")) {
    OK(eoir_set_string(e, target, "spectrum", "s"));
    everything(e, "spectrum 1e10");
  }
  eoir_engine_destroy(e);
}

/* Pushed states at the extremes: refused naming the field, or finite. */
static void states(void) {
  struct {
    int32_t frame;
    double p[3], v[3], q[4], w[3];
    const char* field; /* NULL: accepted */
  } cases[] = {
      {EOIR_FRAME_J2000, {1e308, 0, 0}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, "position[0]"},
      {EOIR_FRAME_J2000, {0, -1e15, 0}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, "position[1]"},
      {EOIR_FRAME_J2000, {0, 0, NAN}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, "position[2]"},
      {EOIR_FRAME_J2000, {7000e3, 0, 1e3}, {3e8, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, "velocity"},
      {EOIR_FRAME_J2000, {7000e3, 0, 1e3}, {1e308, 1e308, 0}, {1, 0, 0, 0}, {0, 0, 0}, "velocity"},
      {EOIR_FRAME_J2000, {7000e3, 0, 1e3}, {0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0}, "attitude"},
      {EOIR_FRAME_J2000, {7000e3, 0, 1e3}, {0, 0, 0}, {1e200, 0, 0, 0}, {0, 0, 0}, "attitude"},
      {EOIR_FRAME_J2000, {7000e3, 0, 1e3}, {0, 0, 0}, {1, 0, 0, 0}, {1e308, 0, 0}, "angular_velocity"},
      {EOIR_FRAME_GEODETIC, {91, 0, 0}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, "position[0] (latitude)"},
      {EOIR_FRAME_GEODETIC, {0, 1e308, 0}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, "position[1] (longitude)"},
      {EOIR_FRAME_GEODETIC, {0, 0, 1e308}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, "position[2] (height)"},
      {7, {0, 0, 0}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, "frame"},
      /* accepted: the far edge of the solar system, receding near c, tumbling */
      {EOIR_FRAME_J2000, {7000e3, 0, 1e14}, {0, 0, 2.99e8}, {1, 0, 0, 0}, {0, 0, 1e3}, NULL},
      /* the target at the sensor (zero range), and inside the Earth */
      {EOIR_FRAME_J2000, {7000e3, 0, 0}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, NULL},
      {EOIR_FRAME_J2000, {0, 0, 0}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, NULL},
      /* geodetic extremes: the pole, longitude 360, deep inside the Earth */
      {EOIR_FRAME_GEODETIC, {90, 360, -6e6}, {0, 0, 0}, {1, 0, 0, 0}, {0, 0, 0}, NULL},
  };
  size_t i;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    eoir_engine e = scene(EOIR_KIND_SATELLITE, space, 0);
    eoir_state s;
    eoir_status st;
    char label[96];
    snprintf(label, sizeof label, "state case %u", (unsigned)i);
    memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    s.frame = cases[i].frame;
    memcpy(s.position, cases[i].p, sizeof s.position);
    memcpy(s.velocity, cases[i].v, sizeof s.velocity);
    memcpy(s.attitude, cases[i].q, sizeof s.attitude);
    memcpy(s.angular_velocity, cases[i].w, sizeof s.angular_velocity);
    st = eoir_object_set_state(e, target, NULL, &s);
    if (cases[i].field) refused(st, cases[i].field, label);
    else if (call_ok(st, "set_state", label)) everything(e, label);
    eoir_engine_destroy(e);
  }
}

/* Composite parts at the extremes: refused naming the part's field, or
 * finite. */
static void composites(void) {
  static const struct {
    const char* json;
    const char* field; /* NULL: accepted */
  } cases[] = {
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[1],\"temperature_K\":1e308}]", "composite[0].temperature_K"},
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[1],\"temperature_K\":-1}]", "composite[0].temperature_K"},
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[1e-300]}]", "composite[0].dimensions_m[0]"},
      {"[{\"shape\":\"box\",\"dimensions_m\":[1,1e308,1]}]", "composite[0].dimensions_m[1]"},
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[1],\"offset_m\":[0,1e308,0]}]", "composite[0].offset_m[1]"},
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[1e999]}]", "composite"},
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[1],\"reflectance\":2}]", "composite[0].reflectance"},
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[1],\"orientation_wxyz\":[0,0,0,0]}]", "composite[0].orientation_wxyz"},
      /* accepted: 1 um and 1e12 m parts, far apart, at the hottest */
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[1e-6],\"temperature_K\":1e6},"
       "{\"shape\":\"box\",\"dimensions_m\":[1e-6,1e-6,1e-6],\"offset_m\":[0,0,-1e6]}]",
       NULL},
      {"[{\"shape\":\"sphere\",\"dimensions_m\":[10]},{\"shape\":\"sphere\",\"dimensions_m\":[10]}]", NULL},
  };
  size_t i;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
    eoir_engine e = scene(EOIR_KIND_SATELLITE, space, 0);
    eoir_status st;
    char label[96];
    snprintf(label, sizeof label, "composite case %u", (unsigned)i);
    OK(eoir_set_string(e, target, "shape", "composite"));
    st = eoir_set_string(e, target, "composite", cases[i].json);
    if (cases[i].field) refused(st, cases[i].field, label);
    else if (call_ok(st, "set composite", label)) everything(e, label);
    eoir_engine_destroy(e);
  }
  {
    /* 100,000-deep nesting: refused, no stack overflow */
    const size_t depth = 100000;
    char* deep = (char*)malloc(2 * depth + 1);
    eoir_engine e = scene(EOIR_KIND_SATELLITE, space, 0);
    memset(deep, '[', depth);
    memset(deep + depth, ']', depth);
    deep[2 * depth] = '\0';
    OK(eoir_set_string(e, target, "shape", "composite"));
    refused(eoir_set_string(e, target, "composite", deep), "composite", "composite nested 100000 deep");
    free(deep);
    eoir_engine_destroy(e);
  }
}

/* Times: the accepted dates (1000-01-01 to 3000-01-01 TT, each part within
 * +-1e7 days) in every scale and split; beyond them, refused naming the
 * part. At each accepted extreme the engine renders, reads, saves and loads. */
static void times(void) {
  static const struct {
    double jd1, jd2;
    int accepted;
  } cases[] = {
      {1e308, 0.0, 0},       {-1e308, 0.0, 0},          {0.0, 1e308, 0},          {NAN, 0.0, 0},
      {HUGE_VAL, 0.0, 0},    {2451545.0, NAN, 0},       {1e7 + 1, 0.0, 0},        {5e6, 5e6, 0},
      {0.0, 0.0, 0},         {2086302.5 - 1.0, 0.0, 0}, {2816787.5 + 1.0, 0.0, 0}, {2400000.5, 1e6, 0},
      {2086302.5 + 1.0, 0.0, 1}, {2816787.5 - 1.0, 0.0, 1}, {2400000.5, -313697.0, 1}, {0.0, 2451545.0, 1},
      {2451545.0, 0.0, 1},
  };
  static const int32_t scales[] = {EOIR_TIME_UTC, EOIR_TIME_TAI, EOIR_TIME_TT, EOIR_TIME_TDB};
  size_t i, s;
  for (i = 0; i < sizeof cases / sizeof cases[0]; ++i)
    for (s = 0; s < 4; ++s) {
      char label[128], iso[64];
      eoir_engine e = scene(EOIR_KIND_SATELLITE, space, 0);
      eoir_time t;
      eoir_status st;
      t.scale = scales[s];
      t.jd1 = cases[i].jd1;
      t.jd2 = cases[i].jd2;
      snprintf(label, sizeof label, "time scale %d jd1 = %.17g jd2 = %.17g", (int)scales[s], t.jd1, t.jd2);
      st = eoir_engine_set_time(e, &t);
      if (!cases[i].accepted) {
        refused(st, "time.jd", label);
        refused(eoir_time_to_iso(&t, iso, sizeof iso), "time.jd", label);
        {
          eoir_state state;
          memset(&state, 0, sizeof state);
          state.struct_size = sizeof state;
          state.attitude[0] = 1;
          refused(eoir_object_set_state(e, target, &t, &state), "time", label);
        }
        {
          double v = 0;
          refused(eoir_provider_series(e, "EOIR Sensor Optics", "F-number", "Sensor1", NULL, &t, 1, &v),
                  "times[0].jd", label);
          refused(eoir_snr_constraint(e, "Sensor1", target, &t, &v), "time.jd", label);
        }
      } else if (call_ok(st, "set_time", label)) {
        int32_t out;
        if (s == 0) everything(e, label);
        for (out = EOIR_TIME_UTC; out <= EOIR_TIME_TDB; ++out) {
          eoir_time back;
          if (call_ok(eoir_engine_get_time(e, out, &back), "get_time", label))
            must_be_finite(back.jd1 + back.jd2, "get_time", label);
        }
        call_ok(eoir_time_to_iso(&t, iso, sizeof iso), "time_to_iso", label);
        /* the engine stays able to save and load */
        OK(eoir_state_save(e, EXTREMES_SCD));
        OK(eoir_state_load(e, EXTREMES_SCD));
      }
      eoir_engine_destroy(e);
    }
  remove(EXTREMES_SCD);
}

/* Names that cannot be saved: invalid UTF-8, control characters, too long. */
static void names(void) {
  eoir_engine e = NULL;
  char longname[100];
  memset(longname, 'a', sizeof longname - 1);
  longname[sizeof longname - 1] = '\0';
  OK(eoir_engine_create(NULL, &e));
  refused(eoir_object_add(e, EOIR_KIND_SATELLITE, "bad\xff"), "name", "name 0xff");
  refused(eoir_object_add(e, EOIR_KIND_SATELLITE, "bad\xc3"), "name", "name truncated UTF-8");
  refused(eoir_object_add(e, EOIR_KIND_SATELLITE, "tab\there"), "name", "name control character");
  refused(eoir_object_add(e, EOIR_KIND_SATELLITE, longname), "name", "name too long");
  FAILS(eoir_set_number(e, "Nobody", "temperature_K", 1.0), EOIR_ERR_UNKNOWN_NAME, "Nobody");
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat\xc3\xa9"));
  FAILS(eoir_set_number(e, "Sat\xc3\xa9", "temprature_K", 1.0), EOIR_ERR_UNKNOWN_NAME, "temprature_K");
  OK(eoir_state_save(e, EXTREMES_SCD));
  remove(EXTREMES_SCD);
  eoir_engine_destroy(e);
}

static void sensor(void) { sweep(EOIR_KIND_SATELLITE, "Sensor1", space, 0); }
static void satellite(void) { sweep(EOIR_KIND_SATELLITE, target, space, 0); }
static void aircraft(void) { sweep(EOIR_KIND_AIRCRAFT, target, space, 0); }
static void ground_vehicle(void) { sweep(EOIR_KIND_GROUND_VEHICLE, target, space, 0); }
static void missile(void) { sweep(EOIR_KIND_MISSILE, target, space, 0); }
static void central_body(void) { sweep(EOIR_KIND_SATELLITE, "Earth", earth, 0); }
static void star_field(void) { sweep(EOIR_KIND_SATELLITE, "Stars", space, 1); }
static void site(void) { sweep(EOIR_KIND_SATELLITE, "Site1", space, 0); }

int main(int argc, char** argv) {
  static const struct {
    const char* name;
    void (*run)(void);
  } parts[] = {{"sensor", sensor},         {"satellite", satellite},       {"aircraft", aircraft},
               {"ground_vehicle", ground_vehicle}, {"missile", missile}, {"central_body", central_body},
               {"star_field", star_field}, {"site", site},             {"huge_counts", huge_counts},
               {"spectra", spectra},
               {"states", states},         {"composites", composites},     {"times", times},
               {"names", names}};
  size_t i;
  int ran = 0;
  for (i = 0; i < sizeof parts / sizeof parts[0]; ++i) {
    struct timespec t0, t1;
    if (argc > 1 && strcmp(argv[1], parts[i].name) != 0) continue; /* one part: capi_extremes_test states */
    clock_gettime(CLOCK_MONOTONIC, &t0);
    parts[i].run();
    clock_gettime(CLOCK_MONOTONIC, &t1);
    printf("%-15s %6.2f s\n", parts[i].name, (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    ++ran;
  }
  printf("%d values checked finite\n", checked_values);
  CHECK(ran > 0);
  if (argc == 1) CHECK(checked_values > 100000);
  return CHECK_SUMMARY();
}
