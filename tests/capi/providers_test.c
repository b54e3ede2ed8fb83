/* C ABI: the static data providers reproduce spec 7.6 Table 3 (within 0.1 %,
 * ensquared energy 0.9683 +- 0.0005), and bad provider requests fail. */
#include "table3_sensor.h"

static double get(eoir_engine e, const char* group, const char* element) {
  double v = 0.0 / 0.0;
  OK(eoir_provider_get(e, group, element, "Sensor1", NULL, &v));
  return v;
}

int main(void) {
  eoir_engine e = NULL;
  const char* sp = "EOIR Sensor Spatial Performance";
  const char* rp = "EOIR Radiometric Performance";
  const char* op = "EOIR Sensor Optics";
  double x[512], y[512], v;
  size_t n = 0;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite1"));
  add_table3_sensor(e, "Satellite1", "Sensor1");

  /* spec 7.6 Table 3 */
  CHECK(get(e, sp, "Number of Horizontal Pixels") == 128);
  CHECK(get(e, sp, "Number of Vertical Pixels") == 128);
  NEAR_REL(get(e, sp, "FOV Solid Angle"), 7.6154e-5, 1e-3);
  NEAR_REL(get(e, sp, "Horizontal FOV"), 0.5, 1e-3);
  NEAR_REL(get(e, sp, "IFOV Solid Angle"), 4.648e-9, 1e-3);
  NEAR_REL(get(e, sp, "Horizontal IFOV"), 6.818e-2, 1e-3);
  NEAR_REL(get(e, sp, "Vertical IFOV"), 6.818e-2, 1e-3);
  NEAR_REL(get(e, sp, "Effective FOV Solid Angle"), 7.865e-5, 1e-3);
  NEAR_REL(get(e, sp, "Effective Horizontal FOV"), 0.5081, 1e-3);
  NEAR_REL(get(e, sp, "Effective IFOV Solid Angle"), 4.80e-9, 1.1e-3); /* quoted to 3 digits */
  NEAR_REL(get(e, sp, "Effective Vertical IFOV"), 6.928e-2, 1e-3);
  NEAR_REL(get(e, "EOIR Sensor Spectral Performance", "Low Band Edge Wavelength"), 1.0, 1e-12);
  NEAR_REL(get(e, "EOIR Sensor Spectral Performance", "High Band Edge Wavelength"), 4.0, 1e-12);
  NEAR_REL(get(e, rp, "Peak Irradiance Responsivity"), 5.295e19, 1e-3);
  NEAR_REL(get(e, rp, "Dark NEI"), 1.0e-18, 1e-3);
  NEAR_REL(get(e, rp, "SEI"), 1.0e-15, 1e-3);
  NEAR_REL(get(e, rp, "Peak Radiance Responsivity"), 2.542e11, 1e-3);
  NEAR_REL(get(e, rp, "Dark NER"), 2.083e-10, 1e-3);
  NEAR_REL(get(e, rp, "SER"), 2.083e-7, 1e-3);
  NEAR_REL(get(e, op, "Effective Focal Length"), 147.0, 1e-12);
  NEAR_REL(get(e, op, "F-number"), 3.5, 1e-12);
  NEAR_REL(get(e, op, "Diffraction Wavelength"), 2.5, 1e-12);
  NEAR_REL(get(e, op, "Airy Disk Diameter"), 1.452e-2, 1e-3);
  NEAR_REL(get(e, op, "Rayleigh Resolution"), 7.262e-3, 1e-3);
  NEAR_REL(get(e, op, "Sparrow Resolution"), 5.952e-3, 1e-3);
  v = get(e, op, "Ensquared Energy");
  CHECK(fabs(v - 0.9683) <= 0.0005);

  /* curves */
  OK(eoir_provider_get_curve(e, op, "Diffraction OTF", "Sensor1", NULL, NULL, NULL, 0, &n));
  CHECK(n > 2 && n <= 512);
  OK(eoir_provider_get_curve(e, op, "Diffraction OTF", "Sensor1", NULL, x, y, 512, &n));
  CHECK(x[0] == 0.0 && fabs(y[0] - 1.0) < 1e-12);
  FAILS(eoir_provider_get_curve(e, op, "Diffraction OTF", "Sensor1", NULL, x, y, 1, &n), EOIR_ERR_BUFFER_TOO_SMALL,
        "capacity");
  FAILS(eoir_provider_get(e, op, "Diffraction OTF", "Sensor1", NULL, &v), EOIR_ERR_TYPE_MISMATCH, "curve");
  FAILS(eoir_provider_get_curve(e, op, "F-number", "Sensor1", NULL, x, y, 512, &n), EOIR_ERR_TYPE_MISMATCH, "scalar");

  /* bad requests */
  FAILS(eoir_provider_get(e, "EOIR Nonsense", "F-number", "Sensor1", NULL, &v), EOIR_ERR_UNKNOWN_NAME, "group");
  FAILS(eoir_provider_get(e, op, "Focal Length", "Sensor1", NULL, &v), EOIR_ERR_UNKNOWN_NAME, "Focal Length");
  FAILS(eoir_provider_get(e, op, "F-number", "Sensor9", NULL, &v), EOIR_ERR_UNKNOWN_NAME, "Sensor9");
  FAILS(eoir_provider_get(e, op, "F-number", "Satellite1", NULL, &v), EOIR_ERR_UNKNOWN_NAME, "not a sensor");
  /* reversed band edges are refused when the metrics are evaluated */
  OK(eoir_set_number(e, "Sensor1", "band_low_um", 5.0));
  FAILS(eoir_provider_get(e, op, "F-number", "Sensor1", NULL, &v), EOIR_ERR_OUT_OF_RANGE, "band_high_um");
  OK(eoir_set_number(e, "Sensor1", "band_high_um", 6.0));
  OK(eoir_provider_get(e, op, "F-number", "Sensor1", NULL, &v));

  /* enumeration */
  {
    const char* g = NULL;
    eoir_element_info info;
    size_t i, groups = 0;
    memset(&info, 0, sizeof info);
    info.struct_size = sizeof info;
    for (i = 0; eoir_provider_group_at(i, &g) == EOIR_OK; ++i) ++groups;
    CHECK(groups >= 4);
    OK(eoir_provider_element_at(op, 0, &info));
    CHECK(strcmp(info.name, "Effective Focal Length") == 0 && strcmp(info.unit, "cm") == 0);
    FAILS(eoir_provider_element_at("EOIR Nonsense", 0, &info), EOIR_ERR_UNKNOWN_NAME, "group");
  }
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
