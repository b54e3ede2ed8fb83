/* Spec 7.7.1, footnote 3 (ERRATA): with the atmosphere on, a point target
 * at the temperature of the background right behind it gives SNR 0, as in
 * vacuum, but for the air it hides: the target's irradiance carries the
 * path's own radiance in front of it (eq. 9's L_path, Schwarzschild layer
 * by layer) as the background's radiance does (issue 20 item 5). C99,
 * through the C ABI: a 300 K black sphere of 0.5 m (a point source, spec
 * 7.7.1's sensor) 1 m in front of a 300 K black plate filling the field,
 * seen from 20 km in 8-12 um; the same target 5 km above the plate hides
 * 5 km of air colder than itself and shows. The SNR 1 m in front is below
 * 1e-3 of that (what 1 m of 282 K air behind the target is worth: about
 * 1e-4 of the band's optical depth per metre times B(300 K) - B(282 K));
 * leaving L_path out of the target (the footnote's flaw) would give some
 * 1e4. */
#include <math.h>

#include "check.h"

static eoir_status put(eoir_engine e, const char* name, double h, double w, double x, double y, double z) {
  eoir_state s = state_at(EOIR_FRAME_EARTH_FIXED, 6378137.0 + h, 0.0, 0.0);
  s.attitude[0] = w;
  s.attitude[1] = x;
  s.attitude[2] = y;
  s.attitude[3] = z;
  return eoir_object_set_state(e, name, NULL, &s);
}

static double snr(eoir_engine e) {
  double v = -1;
  OK(eoir_sensor_point_at(e, "Cam", "Tgt"));
  OK(eoir_provider_get(e, "EOIR Sensor-to-Target Metrics", "Signal to Noise Ratio", "Cam", "Tgt", &v));
  return v;
}

int main(void) {
  eoir_engine e = NULL;
  eoir_time t;
  double point = 0, vacuum, seen, above;
  const double c45 = sqrt(0.5);
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T18:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Host"));
  OK(eoir_set_string(e, "Host", "shape", "none"));
  OK(eoir_sensor_add(e, "Cam", "Host"));
  OK(eoir_set_number(e, "Cam", "band_low_um", 8.0));
  OK(eoir_set_number(e, "Cam", "band_high_um", 12.0));
  OK(eoir_set_integer(e, "Cam", "spectral_intervals", 20));
  OK(eoir_set_bool(e, "Cam", "saturation_enabled", 0));
  OK(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Bkg"));
  OK(eoir_set_string(e, "Bkg", "shape", "plate"));
  OK(eoir_set_array(e, "Bkg", "dimensions_m", (const double[]){20000.0, 20000.0}, 2));
  OK(eoir_set_number(e, "Bkg", "temperature_K", 300.0));
  OK(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Tgt"));
  OK(eoir_set_array(e, "Tgt", "dimensions_m", (const double[]){0.5}, 1));
  OK(eoir_set_number(e, "Tgt", "temperature_K", 300.0));
  OK(put(e, "Host", 20000.0, 1, 0, 0, 0));
  OK(put(e, "Bkg", 1000.0, c45, 0, c45, 0)); /* the plate's +z turned to the local vertical (+x) */
  OK(put(e, "Tgt", 1001.0, 1, 0, 0, 0));

  OK(eoir_set_string(e, "Earth", "atmosphere", "none"));
  vacuum = snr(e);
  OK(eoir_provider_get(e, "EOIR Sensor-to-Target Metrics", "Target Is Point Source", "Cam", "Tgt", &point));
  CHECK(point == 1.0);
  CHECK(vacuum == 0.0); /* spec 7.7.1 step 8 */
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  seen = snr(e);
  OK(put(e, "Tgt", 6000.0, 1, 0, 0, 0));
  above = snr(e);
  printf("SNR: vacuum %g, atmosphere 1 m in front %g, 5 km in front %g\n", vacuum, seen, above);
  CHECK(above > 100.0);
  CHECK(seen < 1e-3 * above);
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
