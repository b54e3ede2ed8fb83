/* Builds the spec 7.6 (Valid_Sens_StaticMetrics) sensor through the C ABI. */
#ifndef EOIR_TEST_TABLE3_SENSOR_H
#define EOIR_TEST_TABLE3_SENSOR_H
#include "check.h"

static void add_table3_sensor(eoir_engine e, const char* parent, const char* sensor) {
  static const double sensitivity[2] = {10.0, 1.0e-18}; /* (ms, W/cm^2) */
  static const double saturation[2] = {10.0, 1.0e-15};
  OK(eoir_sensor_add(e, sensor, parent));
  OK(eoir_set_integer(e, sensor, "horizontal_pixels", 128));
  OK(eoir_set_integer(e, sensor, "vertical_pixels", 128));
  OK(eoir_set_number(e, sensor, "horizontal_fov_deg", 0.5));
  OK(eoir_set_number(e, sensor, "vertical_fov_deg", 0.5));
  OK(eoir_set_number(e, sensor, "band_low_um", 1.0));
  OK(eoir_set_number(e, sensor, "band_high_um", 4.0));
  OK(eoir_set_number(e, sensor, "f_number", 3.5));
  OK(eoir_set_number(e, sensor, "focal_length_cm", 147.0));
  OK(eoir_set_number(e, sensor, "defocus_mm", 0.0));
  OK(eoir_set_string(e, sensor, "image_quality", "diffraction_limited"));
  OK(eoir_set_number(e, sensor, "diffraction_wavelength_um", 2.5));
  OK(eoir_set_number(e, sensor, "integration_time_ms", 10.0));
  OK(eoir_set_string(e, sensor, "sensitivity_quantity", "irradiance"));
  OK(eoir_set_array(e, sensor, "sensitivity_pairs", sensitivity, 2));
  OK(eoir_set_string(e, sensor, "saturation_quantity", "irradiance"));
  OK(eoir_set_array(e, sensor, "saturation_pairs", saturation, 2));
  OK(eoir_set_number(e, sensor, "jitter_mrad", 0.0));
}

#endif
