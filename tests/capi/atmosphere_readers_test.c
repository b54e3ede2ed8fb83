/* The atmosphere between the world's objects and the sensor, through the C
 * ABI (issue 20 item 5 in part; spec 4.1.5.3 eq. 9's T_out, 4.3.1.1), C99:
 * a hot point target seen from the ground in a narrow band at 0.55 um,
 * where every term of the optical depth (Rayleigh, aerosol, ozone's
 * Chappuis band) is proportional to its column: the irradiance with the
 * atmosphere on, divided by that in vacuum, is exp(-tau m) with m the air
 * mass, so the logarithms of the ratios at 30 deg and at the zenith stand
 * as Kasten and Young's air mass of the apparent zenith angle (within 2 %:
 * the aerosol's and the ozone's columns slant a little differently from the
 * air's). Seen from above the atmosphere nothing changes, bit for bit; the
 * target's SNR grows with its elevation. */
#include <math.h>

#include "check.h"

static double get(eoir_engine e, const char* element) {
  double v = -1;
  OK(eoir_provider_get(e, "EOIR Sensor-to-Target Metrics", element, "Scope", "Hot", &v));
  return v;
}


/* Irradiance with the atmosphere on over that in vacuum, and the apparent elevation. */
static double ratio(eoir_engine e, double el_deg, double* apparent_deg) {
  double vacuum, seen;
  OK(place_north(e, "Hot", 0.0, 1.0e6, el_deg));
  OK(eoir_set_string(e, "Earth", "atmosphere", "none"));
  vacuum = get(e, "Effective Target Irradiance");
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  seen = get(e, "Effective Target Irradiance");
  *apparent_deg = get(e, "Apparent Target Elevation");
  return seen / vacuum;
}

int main(void) {
  eoir_engine e = NULL;
  eoir_time t;
  double a90, a30, r90, r30, snr30, snr90, m;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T18:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_GROUND_VEHICLE, "Site"));
  OK(eoir_set_string(e, "Site", "shape", "none"));
  OK(eoir_sensor_add(e, "Scope", "Site"));
  OK(eoir_set_number(e, "Scope", "band_low_um", 0.545));
  OK(eoir_set_number(e, "Scope", "band_high_um", 0.555));
  OK(eoir_set_integer(e, "Scope", "spectral_intervals", 4));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Hot"));
  OK(eoir_set_number(e, "Hot", "temperature_K", 3000.0));
  OK(eoir_set_number(e, "Hot", "reflectance", 0.0));
  OK(place_north(e, "Site", 0.0, 0.0, 90.0));

  r90 = ratio(e, 90.0, &a90);
  r30 = ratio(e, 30.0, &a30);
  CHECK(r90 > 0.5 && r90 < 0.8); /* 0.55 um, US76, rural 23 km: about 0.66 */
  CHECK(r30 < r90);
  m = log(r30) / log(r90);
  if (fabs(m / kasten_young(90.0 - a30) - 1.0) >= 0.02)
    printf("ln ratio at 30 deg / at the zenith %g, Kasten-Young %g\n", m, kasten_young(90.0 - a30));
  CHECK(fabs(m / kasten_young(90.0 - a30) - 1.0) < 0.02);

  /* The SNR rises with elevation (the same range: only the air changes). */
  OK(place_north(e, "Hot", 0.0, 1.0e6, 30.0));
  snr30 = get(e, "Signal to Noise Ratio");
  OK(place_north(e, "Hot", 0.0, 1.0e6, 90.0));
  snr90 = get(e, "Signal to Noise Ratio");
  CHECK(snr90 >= snr30);

  /* Above the atmosphere: a sensor at 500 km looking up at the target 1000 km
   * higher sees the same irradiance, bit for bit, with the atmosphere on. */
  OK(place_north(e, "Site", 500e3, 0.0, 90.0));
  OK(place_north(e, "Hot", 500e3, 1.0e6, 90.0));
  OK(eoir_set_string(e, "Earth", "atmosphere", "none"));
  r90 = get(e, "Effective Target Irradiance");
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  CHECK(get(e, "Effective Target Irradiance") == r90);
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
