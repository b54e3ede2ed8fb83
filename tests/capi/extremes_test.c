/* C ABI: no call returns non-finite data with EOIR_OK (issue 11, item 8).
 *
 * Every numeric property of a sensor and of an object is set, one at a time,
 * to the extremes of its advertised range (eoir_property_info: the minimum,
 * or the smallest positive double above an excluded minimum of 0, and the
 * maximum, or the double just below an excluded one); after each value the
 * engine accepts, the frame is rendered and every image kind, the truth, a
 * pick and every data provider (scalars and curves, with and without the
 * target) are read: each call either fails with a status and a message, or
 * returns finite values. The same after the extreme accepted times.
 * Properties that only change the cost of a frame (pixel counts, grid sizes)
 * are tried at their extremes on the static data providers only. */
#include <float.h>
#include <stdlib.h>

#include "check.h"

static int checked_values = 0;

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

static void must_be_finite(double v, const char* what, const char* label) {
  ++check_count;
  ++checked_values;
  if (!isfinite(v)) {
    ++check_failures;
    fprintf(stderr, "%s: %s = %g with EOIR_OK\n", label, what, v);
  }
}

/* The static data providers of Sensor1, target Satellite2 where one is taken. */
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
        const char* target = t ? "Satellite2" : NULL;
        if (info.type == EOIR_TYPE_CURVE) {
          size_t n = 0, k;
          if (!call_ok(eoir_provider_get_curve(e, group, info.name, "Sensor1", target, NULL, NULL, 0, &n), what,
                       label))
            continue;
          {
            double* x = (double*)calloc(n ? n : 1, sizeof *x);
            double* y = (double*)calloc(n ? n : 1, sizeof *y);
            if (call_ok(eoir_provider_get_curve(e, group, info.name, "Sensor1", target, x, y, n, &n), what, label))
              for (k = 0; k < n; ++k) {
                must_be_finite(x[k], what, label);
                must_be_finite(y[k], what, label);
              }
            free(x);
            free(y);
          }
        } else {
          double v = 0;
          if (call_ok(eoir_provider_get(e, group, info.name, "Sensor1", target, &v), what, label)) must_be_finite(v, what, label);
        }
      }
    }
  }
}

/* Renders Sensor1 and reads every image kind, the truth and a pick. */
static void render_and_read(eoir_engine e, const char* label) {
  int32_t kind;
  size_t count = 0, i;
  double snr = 0;
  if (!call_ok(eoir_render(e, "Sensor1"), "render", label)) return;
  for (kind = EOIR_IMAGE_SCENE_RADIANCE; kind <= EOIR_IMAGE_SENSOR_DISPLAY; ++kind) {
    eoir_image_info info;
    size_t n;
    memset(&info, 0, sizeof info);
    info.struct_size = sizeof info;
    if (!call_ok(eoir_image_info_get(e, "Sensor1", kind, &info), "image_info_get", label)) continue;
    must_be_finite(info.boresight_ra_deg + info.boresight_dec_deg + info.up_ra_deg + info.up_dec_deg, "image_info angles",
           label);
    must_be_finite(info.time_jd_utc[0] + info.time_jd_utc[1], "image_info time", label);
    n = (size_t)info.width * info.height;
    CHECK(n > 0);
    if (kind == EOIR_IMAGE_SCENE_DISPLAY || kind == EOIR_IMAGE_SENSOR_DISPLAY) {
      uint8_t* b = (uint8_t*)malloc(n);
      call_ok(eoir_image_get_bytes(e, "Sensor1", kind, b, n), "image_get_bytes", label);
      free(b);
    } else {
      double* v = (double*)malloc(n * sizeof *v);
      if (call_ok(eoir_image_get(e, "Sensor1", kind, v, n), "image_get", label))
        for (i = 0; i < n; ++i) must_be_finite(v[i], kind == 1 ? "scene radiance" : kind == 3 ? "electrons" : "mean", label);
      free(v);
    }
  }
  if (call_ok(eoir_truth_count(e, "Sensor1", &count), "truth_count", label))
    for (i = 0; i < count; ++i) {
      eoir_truth t;
      memset(&t, 0, sizeof t);
      t.struct_size = sizeof t;
      if (!call_ok(eoir_truth_get(e, "Sensor1", i, &t), "truth_get", label)) continue;
      must_be_finite(t.pixel_x, "truth.pixel_x", label);
      must_be_finite(t.pixel_y, "truth.pixel_y", label);
      must_be_finite(t.range_m, "truth.range_m", label);
      must_be_finite(t.effective_irradiance, "truth.effective_irradiance", label);
      must_be_finite(t.effective_radiance, "truth.effective_radiance", label);
      must_be_finite(t.snr, "truth.snr", label);
    }
  {
    eoir_pick p;
    double wl[4096], l[4096];
    size_t n = 0;
    int32_t space;
    memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    for (space = 0; space < 2; ++space)
      if (call_ok(eoir_pick_get(e, "Sensor1", space, 0, 0, &p, wl, l, 4096, &n), "pick_get", label)) {
        must_be_finite(p.range_m, "pick.range_m", label);
        must_be_finite(p.effective_radiance, "pick.effective_radiance", label);
        must_be_finite(p.temperature_K, "pick.temperature_K", label);
        must_be_finite(p.right_ascension_deg + p.declination_deg, "pick RA/Dec", label);
        for (i = 0; i < n && i < 4096; ++i) {
          must_be_finite(wl[i], "pick wavelengths", label);
          must_be_finite(l[i], "pick spectral radiance", label);
        }
      }
  }
  if (call_ok(eoir_snr_constraint(e, "Sensor1", "Satellite2", NULL, &snr), "snr_constraint", label))
    must_be_finite(snr, "snr_constraint", label);
  {
    double wl[4096], irr[4096];
    size_t n = 0;
    if (call_ok(eoir_target_spectrum_get(e, "Sensor1", "Satellite2", wl, irr, 4096, &n), "target_spectrum_get",
                label))
      for (i = 0; i < n && i < 4096; ++i) {
        must_be_finite(wl[i], "target spectrum wavelengths", label);
        must_be_finite(irr[i], "target spectrum", label);
      }
  }
}

static void everything(eoir_engine e, const char* label) {
  render_and_read(e, label);
  read_providers(e, label);
}

static void put(eoir_engine e, const char* name, double x, double y, double z) {
  eoir_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_J2000;
  s.position[0] = x;
  s.position[1] = y;
  s.position[2] = z;
  s.attitude[0] = 1;
  OK(eoir_object_set_state(e, name, NULL, &s));
}

/* A small frame: Sensor1 on Satellite1 looks along J2000 +z at Satellite2,
 * 1000 km away, a 10 m sphere at 300 K. */
static eoir_engine scene(void) {
  eoir_engine e = NULL;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite1"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite2"));
  OK(eoir_sensor_add(e, "Sensor1", "Satellite1"));
  put(e, "Satellite1", 7000e3, 0, 0);
  put(e, "Satellite2", 7000e3, 0, 1000e3);
  OK(eoir_set_string(e, "Satellite2", "shape", "sphere"));
  {
    const double r = 10.0;
    OK(eoir_set_array(e, "Satellite2", "dimensions_m", &r, 1));
  }
  OK(eoir_set_integer(e, "Sensor1", "horizontal_pixels", 8));
  OK(eoir_set_integer(e, "Sensor1", "vertical_pixels", 8));
  OK(eoir_set_number(e, "Sensor1", "horizontal_fov_deg", 0.01));
  OK(eoir_set_number(e, "Sensor1", "vertical_fov_deg", 0.01));
  return e;
}

/* Properties whose extremes only change the cost of a frame (a 16384^2
 * sensor, the largest grids): providers only. */
static int cost_only(const char* name) {
  static const char* const names[] = {"horizontal_pixels", "vertical_pixels", "spectral_intervals",
                                      "samples_per_pixel", "psf_grid_size",    "patch_size_m",
                                      NULL};
  int i;
  for (i = 0; names[i]; ++i)
    if (strcmp(names[i], name) == 0) return 1;
  return 0;
}

/* The extremes of one numeric property of `object`. */
static void sweep_property(const char* object, const eoir_property_info* info) {
  double values[2];
  int k;
  values[0] = info->minimum;
  if ((info->range_open & 1u) && info->minimum == 0) values[0] = DBL_MIN * DBL_EPSILON; /* 5e-324 */
  else if (info->range_open & 1u) values[0] = nextafter(info->minimum, HUGE_VAL);
  values[1] = info->maximum;
  if (info->range_open & 2u) values[1] = nextafter(info->maximum, -HUGE_VAL);
  for (k = 0; k < 2; ++k) {
    char label[160];
    eoir_engine e;
    eoir_status st;
    if (!isfinite(values[k])) continue;
    snprintf(label, sizeof label, "%s.%s = %.17g", object, info->name, values[k]);
    e = scene();
    if (info->type == EOIR_TYPE_INTEGER) st = eoir_set_integer(e, object, info->name, (int64_t)values[k]);
    else if (info->type == EOIR_TYPE_ARRAY) {
      /* every element at the extreme (reference pairs: one pair) */
      double a[3] = {values[k], values[k], values[k]};
      size_t n = 0;
      if (strcmp(info->name, "sensitivity_pairs") == 0 || strcmp(info->name, "saturation_pairs") == 0) {
        a[0] = 1.0; /* a 1 ms integration time, the extreme value */
        n = 2;
      } else {
        eoir_get_array(e, object, info->name, NULL, 0, &n);
        if (n > 3) n = 3;
      }
      st = eoir_set_array(e, object, info->name, a, n);
    } else
      st = eoir_set_number(e, object, info->name, values[k]);
    if (call_ok(st, "set", label)) {
      if (cost_only(info->name)) read_providers(e, label);
      else everything(e, label);
    }
    eoir_engine_destroy(e);
  }
}

static void sweep(const char* object) {
  eoir_engine e = scene();
  size_t i;
  eoir_property_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  for (i = 0; eoir_property_info_at(e, object, i, &info) == EOIR_OK; ++i)
    if (info.type == EOIR_TYPE_NUMBER || info.type == EOIR_TYPE_INTEGER || info.type == EOIR_TYPE_ARRAY)
      sweep_property(object, &info);
  eoir_engine_destroy(e);
}

/* The engine time at the extremes the C ABI accepts. */
static void times(void) {
  static const double jd1[] = {1e308, -1e308, 1e9, -1e9, 0.0, 2451545.0 + 1e6, 2451545.0 - 1e6,
                               2451545.0 + 365250.0, 2451545.0 - 365250.0};
  static const int32_t scales[] = {EOIR_TIME_UTC, EOIR_TIME_TAI, EOIR_TIME_TT, EOIR_TIME_TDB};
  size_t i, s;
  for (i = 0; i < sizeof jd1 / sizeof jd1[0]; ++i)
    for (s = 0; s < 4; ++s) {
      char label[128];
      eoir_engine e = scene();
      eoir_time t;
      t.scale = scales[s];
      t.jd1 = jd1[i];
      t.jd2 = 0.0;
      snprintf(label, sizeof label, "time scale %d jd1 = %.17g", (int)scales[s], jd1[i]);
      if (call_ok(eoir_engine_set_time(e, &t), "set_time", label)) {
        int32_t out;
        char iso[64];
        everything(e, label);
        for (out = EOIR_TIME_UTC; out <= EOIR_TIME_TDB; ++out) {
          eoir_time back;
          if (call_ok(eoir_engine_get_time(e, out, &back), "get_time", label))
            must_be_finite(back.jd1 + back.jd2, "get_time", label);
        }
        call_ok(eoir_time_to_iso(&t, iso, sizeof iso), "time_to_iso", label);
        /* the engine stays able to save */
        OK(eoir_state_save(e, "capi_extremes_test.scd"));
      }
      eoir_engine_destroy(e);
    }
}

/* One value: extremes_test OBJECT PROPERTY VALUE (for exploring). */
static void one(const char* object, const char* property, double value) {
  eoir_engine e = scene();
  char label[160];
  snprintf(label, sizeof label, "%s.%s = %.17g", object, property, value);
  if (call_ok(eoir_set_number(e, object, property, value), "set", label)) everything(e, label);
  else printf("%s: refused: %s\n", label, eoir_last_error());
  eoir_engine_destroy(e);
}

int main(int argc, char** argv) {
  if (argc == 4) {
    one(argv[1], argv[2], atof(argv[3]));
    printf("%d values checked finite\n", checked_values);
    return CHECK_SUMMARY();
  }
  sweep("Sensor1");
  sweep("Satellite2");
  times();
  printf("%d values checked finite\n", checked_values);
  CHECK(checked_values > 100000);
  return CHECK_SUMMARY();
}
