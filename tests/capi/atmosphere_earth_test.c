/* The Earth's surface seen through its atmosphere (issue 20 items 4, 5 and
 * 7 in part; spec 4.1.5.3 eq. 9), C99 through the C ABI: a GEO imager over
 * 0 N 0 E looking at nadir in 8-12 um, the Earth a black body at a uniform
 * 288 K. With the atmosphere on: the nadir radiance falls below the
 * surface's own (the air above is colder: US76's 8-12 um brightness of a
 * 288 K sea level from space is some 4-8 K colder) but stays above a 265 K
 * black body; toward the limb it falls further (limb darkening); a pick's
 * spectral vector, T_out L + L_path interval by interval, integrates to the
 * image's sample (spec 6.2.1) to 1e-9; with the atmosphere off everything is
 * as before, bit for bit. */
#include <math.h>

#include "check.h"

static double pick(eoir_engine e, uint32_t x, uint32_t y, double* spectral_integral) {
  eoir_pick p;
  double wl[64], L[64];
  size_t n = 0, i;
  memset(&p, 0, sizeof p);
  p.struct_size = sizeof p;
  OK(eoir_pick_get(e, "Geo", 1, x, y, &p, wl, L, 64, &n));
  *spectral_integral = 0;
  for (i = 0; i < n && i < 64; ++i) *spectral_integral += L[i] * (4.0 / (double)n);
  return p.effective_radiance;
}

/* Band radiance (W cm^-2 sr^-1) of a black body over 8-12 um, midpoint rule on 400 intervals. */
static double black(double T) {
  double sum = 0, l;
  int i;
  for (i = 0; i < 400; ++i) {
    l = 8.0 + (i + 0.5) * 0.01;
    sum += 1.191042972e4 / pow(l, 5) / (exp(14387.7688 / (l * T)) - 1.0) * 0.01;
  }
  return sum;
}

int main(void) {
  eoir_engine e = NULL;
  eoir_time t;
  const uint32_t centre = 16, off = 29; /* pixels: the nadir, and 7.3 deg from it (the limb is at 8.7) */
  double nadir_vac, nadir_atm, limb_atm, integral, integral_vac, w = 0;
  const eoir_state geo = state_at(EOIR_FRAME_EARTH_FIXED, 42164170.0, 0.0, 0.0);
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T00:00:00Z", &t)); /* local midnight at 0 E: no sunlight */
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_set_string(e, "Earth", "thermal_model", "uniform"));
  OK(eoir_set_string(e, "Earth", "material", "gray_body"));
  OK(eoir_set_number(e, "Earth", "temperature_K", 288.0));
  OK(eoir_set_number(e, "Earth", "reflectance", 0.0));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_set_string(e, "Sat", "shape", "none"));
  OK(eoir_object_set_state(e, "Sat", NULL, &geo));
  OK(eoir_sensor_add(e, "Geo", "Sat"));
  OK(eoir_set_number(e, "Geo", "band_low_um", 8.0));
  OK(eoir_set_number(e, "Geo", "band_high_um", 12.0));
  OK(eoir_set_integer(e, "Geo", "spectral_intervals", 40));
  OK(eoir_set_integer(e, "Geo", "horizontal_pixels", 32));
  OK(eoir_set_integer(e, "Geo", "vertical_pixels", 32));
  OK(eoir_set_number(e, "Geo", "horizontal_fov_deg", 18.0));
  OK(eoir_set_number(e, "Geo", "vertical_fov_deg", 18.0));
  OK(eoir_sensor_point_at(e, "Geo", "Earth"));
  OK(eoir_render(e, "Geo"));
  nadir_vac = pick(e, centre, centre, &integral_vac);
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  OK(eoir_render(e, "Geo"));
  nadir_atm = pick(e, centre, centre, &integral);
  limb_atm = pick(e, off, centre, &w);
  printf("8-12 um from GEO: nadir %g (vacuum %g; black bodies 288 K %g, 265 K %g), near the limb %g\n", nadir_atm,
         nadir_vac, black(288.0), black(265.0), limb_atm);
  CHECK(fabs(nadir_vac / black(288.0) - 1.0) < 1e-3);
  CHECK(nadir_atm < nadir_vac);
  CHECK(nadir_atm > black(265.0));
  CHECK(limb_atm < nadir_atm);
  CHECK(fabs(integral / nadir_atm - 1.0) < 1e-9);
  CHECK(fabs(integral_vac / nadir_vac - 1.0) < 1e-9);
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
