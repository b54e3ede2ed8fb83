/*
 * example_host.c — the thin C99 example host.
 *
 * Loads the engine as a plugin (plugin_loader.h), builds the spec 7.6
 * Valid_Sens_StaticMetrics scenario through the C ABI only, steps the time and
 * prints every static metric as "Group | Element | value | unit" (%.6g).
 * Curves print as "curve(N points)" in the value column.
 *
 * It then computes an SNR access (spec 7.8) through the function table's
 * snr_constraint: a second engine holds a nadir-pointing 24 x 24 deg,
 * 8-12 um sensor on a GEO satellite and a 2 m, 300 K sphere on a circular
 * LEO orbit (7000 km, i = 60 deg, RAAN = 20 deg) over the 288 K Earth; the
 * host moves both on circles it computes itself and pushes their states.
 * Stepping every 60 s over a day and bisecting each change of SNR >= 6 down
 * to 1 ms, it prints the intervals as
 *   "access: START .. STOP (DURATION s)"  and a closing
 *   "access: N intervals with SNR >= 6, E SNR evaluations".
 *
 * Usage: eoir_example_host [LIBRARY]   (else EOIR_LIBRARY, else the build's)
 */
#include <math.h>
#include <stdio.h>
#include <stddef.h>
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

/* ------------------------------------------------------------ SNR access */
#define ACCESS_MIN_SNR 6.0
#define ACCESS_STEP_S 60.0
#define ACCESS_SPAN_S 86400.0
#define ACCESS_TOL_S 0.001
#define PI 3.14159265358979323846
#define MU_EARTH 3.986004418e14 /* m^3/s^2 */

static double access_epoch_jd; /* UTC Julian date of t = 0 (2010-12-08T22:00:00Z) */
static size_t access_evaluations;

/* Body-to-J2000 quaternion {w, x, y, z} of the rotation whose columns are
 * the body axes x, y, z expressed in J2000. */
static void quat_from_axes(const double x[3], const double y[3], const double z[3], double q[4]) {
  const double m00 = x[0], m11 = y[1], m22 = z[2], tr = m00 + m11 + m22;
  if (tr > 0) {
    const double s = 2.0 * sqrt(tr + 1.0);
    q[0] = 0.25 * s;
    q[1] = (y[2] - z[1]) / s;
    q[2] = (z[0] - x[2]) / s;
    q[3] = (x[1] - y[0]) / s;
  } else if (m00 > m11 && m00 > m22) {
    const double s = 2.0 * sqrt(1.0 + m00 - m11 - m22);
    q[0] = (y[2] - z[1]) / s;
    q[1] = 0.25 * s;
    q[2] = (y[0] + x[1]) / s;
    q[3] = (z[0] + x[2]) / s;
  } else if (m11 > m22) {
    const double s = 2.0 * sqrt(1.0 + m11 - m00 - m22);
    q[0] = (z[0] - x[2]) / s;
    q[1] = (y[0] + x[1]) / s;
    q[2] = 0.25 * s;
    q[3] = (z[1] + y[2]) / s;
  } else {
    const double s = 2.0 * sqrt(1.0 + m22 - m00 - m11);
    q[0] = (x[1] - y[0]) / s;
    q[1] = (z[0] + x[2]) / s;
    q[2] = (z[1] + y[2]) / s;
    q[3] = 0.25 * s;
  }
}

/* A circular orbit of radius a (m), inclination i and RAAN raan (rad),
 * argument of latitude u0 at t = 0: J2000 position and velocity at t. */
static void circular(double a, double i, double raan, double u0, double t, double pos[3], double vel[3]) {
  const double n = sqrt(MU_EARTH / (a * a * a)), u = u0 + n * t, v = n * a;
  const double p[3] = {cos(raan), sin(raan), 0.0};
  const double q[3] = {-sin(raan) * cos(i), cos(raan) * cos(i), sin(i)};
  int k;
  for (k = 0; k < 3; ++k) {
    pos[k] = a * (cos(u) * p[k] + sin(u) * q[k]);
    vel[k] = v * (-sin(u) * p[k] + cos(u) * q[k]);
  }
}

static eoir_time access_time(double t) {
  eoir_time time;
  time.scale = EOIR_TIME_UTC;
  time.jd1 = access_epoch_jd;
  time.jd2 = t / 86400.0;
  return time;
}

/* Pushes both states at t (seconds from the epoch) and returns the SNR
 * through the constraint callback, or -1 on an engine error. */
static double access_snr(eoir_engine engine, double t) {
  eoir_time time = access_time(t);
  eoir_state geo, leo;
  double x[3], y[3], z[3], r, snr = 0.0;
  int k;
  memset(&geo, 0, sizeof geo);
  geo.struct_size = sizeof geo;
  geo.frame = EOIR_FRAME_J2000;
  circular(42164.17e3, 0.0, 0.0, 0.0, t, geo.position, geo.velocity);
  /* Nadir: body +z toward the Earth's centre, +y along the orbit normal. */
  r = sqrt(geo.position[0] * geo.position[0] + geo.position[1] * geo.position[1] + geo.position[2] * geo.position[2]);
  for (k = 0; k < 3; ++k) z[k] = -geo.position[k] / r;
  y[0] = 0.0;
  y[1] = 0.0;
  y[2] = 1.0;
  x[0] = y[1] * z[2] - y[2] * z[1];
  x[1] = y[2] * z[0] - y[0] * z[2];
  x[2] = y[0] * z[1] - y[1] * z[0];
  quat_from_axes(x, y, z, geo.attitude);
  memset(&leo, 0, sizeof leo);
  leo.struct_size = sizeof leo;
  leo.frame = EOIR_FRAME_J2000;
  circular(7000e3, 60.0 * PI / 180.0, 20.0 * PI / 180.0, 0.0, t, leo.position, leo.velocity);
  leo.attitude[0] = 1.0;
  if (failed(api->object_set_state(engine, "GEO", &time, &geo), "object_set_state GEO") ||
      failed(api->object_set_state(engine, "LEO", &time, &leo), "object_set_state LEO") ||
      failed(api->snr_constraint(engine, "Imager", "LEO", &time, &snr), "snr_constraint"))
    return -1.0;
  ++access_evaluations;
  return snr;
}

static void print_time(double t, char* buf, size_t capacity) {
  eoir_time time = access_time(t);
  if (api->time_to_iso(&time, buf, capacity) != EOIR_OK) snprintf(buf, capacity, "t+%.3f s", t);
}

/* Builds the GEO/LEO engine, steps a day and bisects every change of
 * SNR >= 6; returns 0 on success. */
static int run_access(void) {
  eoir_engine engine = NULL;
  eoir_time epoch;
  const double sensitivity[2] = {10.0, 4e-18};
  const double radius[1] = {2.0};
  double t, prev_t = 0.0, start = 0.0, snr;
  int prev_in = 0, in, rc = 1;
  size_t steps, n, intervals = 0;
  char a[64], b[64];

  if (api->struct_size < offsetof(eoir_api_v1, truth_get) + sizeof api->truth_get || api->snr_constraint == NULL) {
    fprintf(stderr, "eoir_example_host: the engine has no snr_constraint (ABI 1.2 needed)\n");
    return 1;
  }
  CHECK(api->time_from_iso("2010-12-08T22:00:00Z", &epoch), "time_from_iso");
  access_epoch_jd = epoch.jd1 + epoch.jd2;
  CHECK(api->engine_create(NULL, &engine), "engine_create (access)");
  CHECK(api->object_add(engine, EOIR_KIND_CENTRAL_BODY, "Earth"), "object_add Earth");
  CHECK(api->set_number(engine, "Earth", "temperature_K", 288.0), "Earth temperature_K");
  CHECK(api->object_add(engine, EOIR_KIND_SATELLITE, "GEO"), "object_add GEO");
  CHECK(api->set_string(engine, "GEO", "shape", "none"), "GEO shape");
  CHECK(api->object_add(engine, EOIR_KIND_SATELLITE, "LEO"), "object_add LEO");
  CHECK(api->set_string(engine, "LEO", "shape", "sphere"), "LEO shape");
  CHECK(api->set_array(engine, "LEO", "dimensions_m", radius, 1), "LEO dimensions_m");
  CHECK(api->set_string(engine, "LEO", "material", "gray_body"), "LEO material");
  CHECK(api->set_number(engine, "LEO", "reflectance", 0.0), "LEO reflectance");
  CHECK(api->set_number(engine, "LEO", "temperature_K", 300.0), "LEO temperature_K");
  CHECK(api->sensor_add(engine, "Imager", "GEO"), "sensor_add Imager");
  CHECK(api->set_number(engine, "Imager", "band_low_um", 8.0), "band_low_um");
  CHECK(api->set_number(engine, "Imager", "band_high_um", 12.0), "band_high_um");
  CHECK(api->set_integer(engine, "Imager", "spectral_intervals", 10), "spectral_intervals");
  CHECK(api->set_integer(engine, "Imager", "horizontal_pixels", 256), "horizontal_pixels");
  CHECK(api->set_integer(engine, "Imager", "vertical_pixels", 256), "vertical_pixels");
  CHECK(api->set_number(engine, "Imager", "horizontal_fov_deg", 24.0), "horizontal_fov_deg");
  CHECK(api->set_number(engine, "Imager", "vertical_fov_deg", 24.0), "vertical_fov_deg");
  CHECK(api->set_number(engine, "Imager", "focal_length_cm", 10.0), "focal_length_cm");
  CHECK(api->set_number(engine, "Imager", "f_number", 2.0), "f_number");
  CHECK(api->set_number(engine, "Imager", "diffraction_wavelength_um", 10.0), "diffraction_wavelength_um");
  CHECK(api->set_number(engine, "Imager", "integration_time_ms", 10.0), "integration_time_ms");
  CHECK(api->set_string(engine, "Imager", "sensitivity_quantity", "irradiance"), "sensitivity_quantity");
  CHECK(api->set_array(engine, "Imager", "sensitivity_pairs", sensitivity, 2), "sensitivity_pairs");
  CHECK(api->set_bool(engine, "Imager", "saturation_enabled", 0), "saturation_enabled");

  steps = (size_t)(ACCESS_SPAN_S / ACCESS_STEP_S);
  for (n = 0; n <= steps; ++n) {
    t = (double)n * ACCESS_STEP_S;
    if ((snr = access_snr(engine, t)) < 0) goto fail;
    in = snr >= ACCESS_MIN_SNR;
    if (n > 0 && in != prev_in) {
      /* Bisection on the predicate between the two steps. */
      double lo = prev_t, hi = t;
      while (hi - lo > ACCESS_TOL_S) {
        const double mid = 0.5 * (lo + hi);
        if ((snr = access_snr(engine, mid)) < 0) goto fail;
        if ((snr >= ACCESS_MIN_SNR) == prev_in) lo = mid;
        else hi = mid;
      }
      if (in) {
        start = hi;
      } else {
        print_time(start, a, sizeof a);
        print_time(lo, b, sizeof b);
        printf("access: %s .. %s (%.3f s)\n", a, b, lo - start);
        ++intervals;
      }
    } else if (n == 0 && in) {
      start = 0.0;
    }
    prev_in = in;
    prev_t = t;
  }
  if (prev_in) {
    print_time(start, a, sizeof a);
    print_time(prev_t, b, sizeof b);
    printf("access: %s .. %s (%.3f s)\n", a, b, prev_t - start);
    ++intervals;
  }
  printf("access: %lu intervals with SNR >= %g, %lu SNR evaluations\n", (unsigned long)intervals, ACCESS_MIN_SNR,
         (unsigned long)access_evaluations);
  rc = 0;
fail:
  api->engine_destroy(engine);
  return rc;
}

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
  rc = run_access();

fail:
  api->engine_destroy(engine);
  eoir_loader_close(&plugin);
  return rc;
}
