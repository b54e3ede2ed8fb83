/* A program built against an installed EOIR tree (find_package(eoir) or
 * pkg-config eoir): links libeoir directly, creates an engine, evaluates the
 * spec 7.6 ensquared energy of a default sensor and prints it. */
#include <stdio.h>

#include <eoir/eoir.h>

int main(void) {
  eoir_engine e = NULL;
  double ee = 0.0;
  if (eoir_engine_create(NULL, &e) != EOIR_OK) return fprintf(stderr, "create: %s\n", eoir_last_error()), 1;
  if (eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat") != EOIR_OK || eoir_sensor_add(e, "Cam", "Sat") != EOIR_OK ||
      eoir_provider_get(e, "EOIR Sensor Optics", "Ensquared Energy", "Cam", NULL, &ee) != EOIR_OK) {
    fprintf(stderr, "engine: %s\n", eoir_last_error());
    eoir_engine_destroy(e);
    return 1;
  }
  printf("eoir %s: ensquared energy %.4f\n", eoir_version_string(), ee);
  eoir_engine_destroy(e);
  return 0;
}
