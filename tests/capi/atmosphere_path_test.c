/* The atmosphere between a ground sensor and a satellite through the C ABI
 * (issue 20 items 1, 2, 9; spec 4.3.1.1, 6.2.5.4), C99: the Earth's
 * `atmosphere` properties, and the "EOIR Sensor-to-Target Metrics" group. From the
 * ground at sea level the air mass toward a satellite follows Kasten and
 * Young (1989) of the apparent zenith angle within 1 % to 85 deg; straight
 * up it is 1 (6.2.5.4); from an aircraft at 10 km it is the column above,
 * p(10 km) / p0 = 0.2615 of US76; with the atmosphere off every element is
 * 0; only the Earth's atmosphere can be switched on; bad values name the
 * property. The path's elements are sensor-to-target metrics. */
#include <math.h>

#include "check.h"

static double element(eoir_engine e, const char* name, const char* target) {
  double v = -1;
  OK(eoir_provider_get(e, "EOIR Sensor-to-Target Metrics", name, "Scope", target, &v));
  return v;
}

/* Earth-fixed position at distance L from the point (0 N, 0 E, h) at
 * elevation el_deg toward the north. */

int main(void) {
  eoir_engine e = NULL;
  eoir_time t;
  double el;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T18:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Moon"));
  OK(eoir_object_add(e, EOIR_KIND_GROUND_VEHICLE, "Site"));
  OK(eoir_set_string(e, "Site", "shape", "none"));
  OK(eoir_sensor_add(e, "Scope", "Site"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(place_north(e, "Site", 0.0, 0.0, 90.0));
  OK(place_north(e, "Sat", 0.0, 3.0e6, 90.0));

  /* Off by default: every element 0. */
  CHECK(element(e, "Atmosphere On", "Sat") == 0.0);
  CHECK(element(e, "Air Mass", "Sat") == 0.0);

  /* Only the Earth's; bad values name the property. */
  FAILS(eoir_set_string(e, "Moon", "atmosphere", "simple"), EOIR_ERR_NOT_ALLOWED, "atmosphere");
  FAILS(eoir_set_string(e, "Earth", "atmosphere", "thick"), EOIR_ERR_UNKNOWN_NAME, "atmosphere");
  FAILS(eoir_set_number(e, "Earth", "visibility_km", 0.1), EOIR_ERR_OUT_OF_RANGE, "visibility_km");
  FAILS(eoir_set_number(e, "Earth", "visibility_km", NAN), EOIR_ERR_OUT_OF_RANGE, "visibility_km");
  FAILS(eoir_set_string(e, "Earth", "atmosphere_profile", "martian"), EOIR_ERR_UNKNOWN_NAME, "atmosphere_profile");
  FAILS(eoir_set_number(e, "Earth", "water_vapor_scale", -1), EOIR_ERR_OUT_OF_RANGE, "water_vapor_scale");

  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  OK(eoir_set_string(e, "Earth", "aerosol_model", "none"));
  CHECK(element(e, "Atmosphere On", "Sat") == 1.0);
  CHECK(fabs(element(e, "Sensor Altitude", "Sat")) < 1e-3);
  CHECK(fabs(element(e, "Air Mass", "Sat") - 1.0) < 1e-3);
  CHECK(fabs(element(e, "Target Elevation", "Sat") - 90.0) < 1e-6);
  /* US76 with the AFGL US-standard absorbers: 1.4164 cm, 0.3438 atm-cm
   * (the MODTRAN columns of ASTM G173-03), the Rayleigh depth 0.0971. */
  CHECK(fabs(element(e, "Water Vapor Column", "Sat") / 1.4164 - 1.0) < 0.01);
  CHECK(fabs(element(e, "Ozone Column", "Sat") / 0.3438 - 1.0) < 0.01);
  CHECK(fabs(element(e, "Rayleigh Optical Depth", "Sat") / 0.0971 - 1.0) < 0.01);
  CHECK(element(e, "Aerosol Optical Depth", "Sat") == 0.0);
  for (el = 5.0; el <= 90.0; el += 5.0) {
    double m, apparent;
    OK(place_north(e, "Sat", 0.0, 3.0e6, el));
    m = element(e, "Air Mass", "Sat");
    apparent = element(e, "Apparent Target Elevation", "Sat");
    CHECK(apparent >= el && apparent - el < 0.2);
    if (fabs(m / kasten_young(90.0 - apparent) - 1.0) >= 0.01)
      printf("elevation %g (apparent %g): air mass %g, Kasten-Young %g\n", el, apparent, m, kasten_young(90.0 - apparent));
    CHECK(fabs(m / kasten_young(90.0 - apparent) - 1.0) < 0.01);
  }
  /* The rural aerosol at 23 km visibility: LOWTRAN 7's 0.324 straight up. */
  OK(eoir_set_string(e, "Earth", "aerosol_model", "rural"));
  OK(place_north(e, "Sat", 0.0, 3.0e6, 90.0));
  CHECK(fabs(element(e, "Aerosol Optical Depth", "Sat") - 0.324) < 0.003);
  /* An aircraft at 10 km looks through the column above it. */
  OK(place_north(e, "Site", 10000.0, 0.0, 90.0));
  CHECK(fabs(element(e, "Sensor Altitude", "Sat") - 10.0) < 1e-3);
  CHECK(fabs(element(e, "Air Mass", "Sat") / 0.2615 - 1.0) < 0.005);
  /* Above the atmosphere nothing is crossed. */
  OK(place_north(e, "Site", 500e3, 0.0, 90.0));
  CHECK(element(e, "Air Mass", "Sat") == 0.0);
  CHECK(element(e, "Path Length in Atmosphere", "Sat") == 0.0);
  FAILS(eoir_provider_get(e, "EOIR Sensor-to-Target Metrics", "Air Mas", "Scope", "Sat", &el), EOIR_ERR_UNKNOWN_NAME, "Air Mas");
  /* The group's own metrics still answer beside them. */
  CHECK(element(e, "Range to Target", "Sat") > 0);
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
