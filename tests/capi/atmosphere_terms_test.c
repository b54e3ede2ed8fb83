/* Eq. 9 term by term through the C ABI (issue 20 item 5; spec 4.1.5.3, the
 * components of 6.2.5.4), C99: eoir_pick_term_get on a GEO imager over 0 N
 * 0 E at local noon, 0.4-0.7 um in 6 intervals, the Earth a gray 0.3
 * reflector.
 * - In vacuum: T_out 1, the path's terms and DownWelling 0, at the sensor
 *   what leaves the surface, exactly.
 * - With the atmosphere: interval by interval at_sensor = surface x T_out +
 *   L_path + L_scatter (1e-12); T_out in (0, 1) and rising with wavelength
 *   (Rayleigh); L_scatter positive and blue (its first interval over 1.5x
 *   its last; Rayleigh alone would give 6.4x); DownWelling positive and a
 *   part of what leaves the surface, and with `downwelling` off that part
 *   and only it is gone (1e-12).
 * - Off the disc the line crosses no air: T_out 1, nothing added.
 * - A term outside the enum is EOIR_ERR_OUT_OF_RANGE naming "term"; a NULL
 *   buffer asks the size.
 * - From 500 km at nadir in coarse mode (patches ~785 km) T_out at 0.55 um
 *   without aerosol is the vertical column's, LOWTRAN 7's 0.882 (+-0.02),
 *   and equals smooth mode's (1e-9): the path is the sample's line of
 *   sight, not its patch centre's (which gave 0.840). */
#include <math.h>

#include "check.h"

enum { N = 6 };

static void term(eoir_engine e, uint32_t x, uint32_t y, int32_t which, double* out) {
  size_t n = 0;
  OK(eoir_pick_term_get(e, "Geo", 1, x, y, which, out, N, &n));
  CHECK(n == N);
}

/* Every term of pixel (x, y), in the enum's order. */
static void all_terms(eoir_engine e, uint32_t x, uint32_t y, double* surface, double* down, double* T, double* L,
                      double* S, double* at) {
  term(e, x, y, EOIR_PICK_TERM_SURFACE, surface);
  term(e, x, y, EOIR_PICK_TERM_DOWNWELLING, down);
  term(e, x, y, EOIR_PICK_TERM_TRANSMITTANCE, T);
  term(e, x, y, EOIR_PICK_TERM_PATH_THERMAL, L);
  term(e, x, y, EOIR_PICK_TERM_PATH_SCATTER, S);
  term(e, x, y, EOIR_PICK_TERM_AT_SENSOR, at);
}

int main(void) {
  eoir_engine e = NULL;
  eoir_time t;
  double surface[N], down[N], T[N], L[N], S[N], at[N], surface_off[N], down_off[N];
  size_t n = 0;
  int i;
  const eoir_state geo = state_at(EOIR_FRAME_EARTH_FIXED, 42164170.0, 0.0, 0.0);
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-03-20T12:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_set_string(e, "Earth", "material", "gray_body"));
  OK(eoir_set_number(e, "Earth", "reflectance", 0.3));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_set_string(e, "Sat", "shape", "none"));
  OK(eoir_object_set_state(e, "Sat", NULL, &geo));
  OK(eoir_sensor_add(e, "Geo", "Sat"));
  OK(eoir_set_number(e, "Geo", "band_low_um", 0.4));
  OK(eoir_set_number(e, "Geo", "band_high_um", 0.7));
  OK(eoir_set_integer(e, "Geo", "spectral_intervals", N));
  OK(eoir_set_integer(e, "Geo", "horizontal_pixels", 32));
  OK(eoir_set_integer(e, "Geo", "vertical_pixels", 32));
  OK(eoir_set_number(e, "Geo", "horizontal_fov_deg", 18.0));
  OK(eoir_set_number(e, "Geo", "vertical_fov_deg", 18.0));
  OK(eoir_sensor_point_at(e, "Geo", "Earth"));

  OK(eoir_render(e, "Geo"));
  all_terms(e, 16, 16, surface, down, T, L, S, at);
  for (i = 0; i < N; ++i) {
    CHECK(T[i] == 1.0 && L[i] == 0.0 && S[i] == 0.0 && down[i] == 0.0);
    CHECK(surface[i] > 0 && at[i] == surface[i]);
  }

  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  OK(eoir_render(e, "Geo"));
  all_terms(e, 16, 16, surface, down, T, L, S, at);
  printf("nadir at noon, 0.4-0.7 um: T_out %.3f..%.3f, L_scatter %.3g..%.3g, DownWelling %.3g of %.3g leaving\n", T[0],
         T[N - 1], S[0], S[N - 1], down[0], surface[0]);
  for (i = 0; i < N; ++i) {
    NEAR_REL(at[i], surface[i] * T[i] + L[i] + S[i], 1e-12);
    CHECK(T[i] > 0.0 && T[i] < 1.0);
    CHECK(S[i] > 0.0);
    CHECK(down[i] > 0.0 && down[i] < surface[i]);
    if (i > 0) CHECK(T[i] > T[i - 1]);
  }
  CHECK(S[0] > 1.5 * S[N - 1]);

  OK(eoir_set_bool(e, "Earth", "downwelling", 0));
  OK(eoir_render(e, "Geo"));
  term(e, 16, 16, EOIR_PICK_TERM_SURFACE, surface_off);
  term(e, 16, 16, EOIR_PICK_TERM_DOWNWELLING, down_off);
  for (i = 0; i < N; ++i) {
    CHECK(down_off[i] == 0.0);
    NEAR_REL(surface[i] - surface_off[i], down[i], 1e-12);
  }

  term(e, 0, 0, EOIR_PICK_TERM_TRANSMITTANCE, T); /* 12.7 deg off the nadir: past the limb and its air */
  term(e, 0, 0, EOIR_PICK_TERM_PATH_SCATTER, S);
  for (i = 0; i < N; ++i) CHECK(T[i] == 1.0 && S[i] == 0.0);

  OK(eoir_pick_term_get(e, "Geo", 1, 16, 16, EOIR_PICK_TERM_AT_SENSOR, NULL, 0, &n));
  CHECK(n == N);
  FAILS(eoir_pick_term_get(e, "Geo", 1, 16, 16, 6, at, N, &n), EOIR_ERR_OUT_OF_RANGE, "term");
  FAILS(eoir_pick_term_get(e, "Geo", 1, 16, 16, EOIR_PICK_TERM_SURFACE, at, 2, &n), EOIR_ERR_BUFFER_TOO_SMALL,
        "capacity");
  eoir_engine_destroy(e);

  {
    double coarse = 0, smooth = 0;
    const eoir_state leo = state_at(EOIR_FRAME_EARTH_FIXED, 6378137.0 + 500e3, 0.0, 0.0);
    OK(eoir_engine_create(NULL, &e));
    OK(eoir_engine_set_time(e, &t));
    OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
    OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
    OK(eoir_set_string(e, "Earth", "aerosol_model", "none"));
    OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Leo"));
    OK(eoir_set_string(e, "Leo", "shape", "none"));
    OK(eoir_object_set_state(e, "Leo", NULL, &leo));
    OK(eoir_sensor_add(e, "Geo", "Leo"));
    OK(eoir_set_number(e, "Geo", "band_low_um", 0.549));
    OK(eoir_set_number(e, "Geo", "band_high_um", 0.551));
    OK(eoir_set_integer(e, "Geo", "spectral_intervals", 1));
    OK(eoir_set_integer(e, "Geo", "horizontal_pixels", 3));
    OK(eoir_set_integer(e, "Geo", "vertical_pixels", 3));
    OK(eoir_set_number(e, "Geo", "horizontal_fov_deg", 0.01));
    OK(eoir_set_number(e, "Geo", "vertical_fov_deg", 0.01));
    OK(eoir_sensor_point_at(e, "Geo", "Earth"));
    OK(eoir_set_string(e, "Geo", "scene_mode", "coarse"));
    OK(eoir_render(e, "Geo"));
    OK(eoir_pick_term_get(e, "Geo", 1, 1, 1, EOIR_PICK_TERM_TRANSMITTANCE, &coarse, 1, &n));
    OK(eoir_set_string(e, "Geo", "scene_mode", "smooth"));
    OK(eoir_render(e, "Geo"));
    OK(eoir_pick_term_get(e, "Geo", 1, 1, 1, EOIR_PICK_TERM_TRANSMITTANCE, &smooth, 1, &n));
    printf("T_out at nadir from 500 km, 0.55 um: coarse %.4f, smooth %.4f (LOWTRAN 7: 0.882)\n", coarse, smooth);
    NEAR_ABS(coarse, 0.882, 0.02);
    NEAR_ABS(coarse, smooth, 1e-9);
    eoir_engine_destroy(e);
  }
  return CHECK_SUMMARY();
}
