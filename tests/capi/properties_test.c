/* C ABI: typed properties of objects and sensors, and bad values. */
#include "check.h"

int main(void) {
  eoir_engine e = NULL;
  double d = 0, dims[3] = {1, 2, 3}, buf[4];
  int64_t n = 0;
  int32_t b = 0;
  size_t count = 0;
  char s[64];
  eoir_property_info info;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite1"));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_sensor_add(e, "Sensor1", "Satellite1"));

  /* objects: shape, dimensions, material, temperature */
  OK(eoir_set_string(e, "Satellite1", "shape", "box"));
  OK(eoir_get_array(e, "Satellite1", "dimensions_m", NULL, 0, &count));
  CHECK(count == 3);
  OK(eoir_set_array(e, "Satellite1", "dimensions_m", dims, 3));
  FAILS(eoir_set_array(e, "Satellite1", "dimensions_m", dims, 2), EOIR_ERR_OUT_OF_RANGE, "dimensions_m");
  dims[1] = -2;
  FAILS(eoir_set_array(e, "Satellite1", "dimensions_m", dims, 3), EOIR_ERR_OUT_OF_RANGE, "dimensions_m[1]");
  FAILS(eoir_set_string(e, "Satellite1", "shape", "torus"), EOIR_ERR_UNKNOWN_NAME, "torus");
  FAILS(eoir_set_string(e, "Satellite1", "material", "unobtainium"), EOIR_ERR_UNKNOWN_NAME, "material");
  OK(eoir_set_string(e, "Satellite1", "material", "gold_mli"));
  OK(eoir_get_string(e, "Satellite1", "material", s, sizeof s));
  CHECK(strcmp(s, "gold_mli") == 0);
  FAILS(eoir_get_string(e, "Satellite1", "material", s, 3), EOIR_ERR_BUFFER_TOO_SMALL, "capacity");
  OK(eoir_set_number(e, "Satellite1", "temperature_K", 0.0)); /* 0 K is valid (spec 7.4.1) */
  FAILS(eoir_set_number(e, "Satellite1", "temperature_K", -1.0), EOIR_ERR_OUT_OF_RANGE, "temperature_K");
  FAILS(eoir_set_number(e, "Satellite1", "temperature_K", 0.0 / 0.0), EOIR_ERR_OUT_OF_RANGE, "temperature_K");
  FAILS(eoir_set_number(e, "Satellite1", "reflectance", 1.5), EOIR_ERR_OUT_OF_RANGE, "reflectance");
  /* Issue 25 item 11: messages quote a value with the digits that read back
   * as it (179.9999 was "got 180" against a 179.9 limit; 5e-324 was 0). */
  FAILS(eoir_set_number(e, "Sensor1", "horizontal_fov_deg", 179.9999), EOIR_ERR_OUT_OF_RANGE,
        "horizontal_fov_deg: must be in [1e-06, 179.9] deg, got 179.9999");
  FAILS(eoir_set_number(e, "Satellite1", "temperature_K", -5e-324), EOIR_ERR_OUT_OF_RANGE, "got -5e-324");
  FAILS(eoir_set_number(e, "Satellite1", "reflectance", 1.0000000000000002), EOIR_ERR_OUT_OF_RANGE,
        "got 1.0000000000000002");
  FAILS(eoir_set_number(e, "Satellite1", "wingspan", 1.0), EOIR_ERR_UNKNOWN_NAME, "wingspan");
  FAILS(eoir_set_string(e, "Satellite1", "temperature_K", "hot"), EOIR_ERR_TYPE_MISMATCH, "temperature_K");
  FAILS(eoir_set_string(e, "Earth", "shape", "box"), EOIR_ERR_NOT_ALLOWED, "fixed");
  OK(eoir_get_array(e, "Earth", "dimensions_m", buf, 4, &count));
  CHECK(count == 2 && buf[0] == 6378137.0);

  /* sensors */
  FAILS(eoir_set_integer(e, "Sensor1", "horizontal_pixels", 0), EOIR_ERR_OUT_OF_RANGE, "horizontal_pixels");
  FAILS(eoir_set_integer(e, "Sensor1", "vertical_pixels", -5), EOIR_ERR_OUT_OF_RANGE, "vertical_pixels");
  FAILS(eoir_set_number(e, "Sensor1", "horizontal_pixels", 12.5), EOIR_ERR_OUT_OF_RANGE, "horizontal_pixels");
  OK(eoir_set_number(e, "Sensor1", "horizontal_pixels", 256.0)); /* a whole number is an integer */
  OK(eoir_get_integer(e, "Sensor1", "horizontal_pixels", &n));
  CHECK(n == 256);
  OK(eoir_get_number(e, "Sensor1", "horizontal_pixels", &d)); /* integers read as numbers */
  CHECK(d == 256.0);
  FAILS(eoir_set_number(e, "Sensor1", "horizontal_fov_deg", 1.0 / 0.0), EOIR_ERR_OUT_OF_RANGE, "horizontal_fov_deg");
  FAILS(eoir_set_number(e, "Sensor1", "f_number", 0.0), EOIR_ERR_OUT_OF_RANGE, "f_number");
  FAILS(eoir_set_string(e, "Sensor1", "image_quality", "superb"), EOIR_ERR_UNKNOWN_NAME, "image_quality");
  OK(eoir_set_string(e, "Sensor1", "image_quality", "mild"));
  OK(eoir_get_number(e, "Sensor1", "wavefront_error_rms_waves", &d));
  CHECK(d == 0.14);
  OK(eoir_set_number(e, "Sensor1", "wavefront_error_rms_waves", 0.21));
  OK(eoir_get_string(e, "Sensor1", "image_quality", s, sizeof s));
  CHECK(strcmp(s, "custom") == 0);
  /* A custom W_rms equal to a preset's stays custom, and a preset given its
   * own W_rms stays itself: states apply image_quality, then W_rms, and
   * load as saved (issue 25, round trips; it became "mild"). */
  OK(eoir_set_number(e, "Sensor1", "wavefront_error_rms_waves", 0.14));
  OK(eoir_get_string(e, "Sensor1", "image_quality", s, sizeof s));
  CHECK(strcmp(s, "custom") == 0);
  OK(eoir_set_string(e, "Sensor1", "image_quality", "mild"));
  OK(eoir_set_number(e, "Sensor1", "wavefront_error_rms_waves", 0.14));
  OK(eoir_get_string(e, "Sensor1", "image_quality", s, sizeof s));
  CHECK(strcmp(s, "mild") == 0);
  {
    double nine[18];
    int i;
    for (i = 0; i < 18; i += 2) {
      nine[i] = 1.0 + i;
      nine[i + 1] = 1e-18;
    }
    FAILS(eoir_set_array(e, "Sensor1", "sensitivity_pairs", nine, 18), EOIR_ERR_LIMIT_EXCEEDED, "sensitivity_pairs");
    FAILS(eoir_set_array(e, "Sensor1", "sensitivity_pairs", nine, 3), EOIR_ERR_OUT_OF_RANGE, "sensitivity_pairs");
    OK(eoir_set_array(e, "Sensor1", "sensitivity_pairs", nine, 16));
  }
  OK(eoir_set_bool(e, "Sensor1", "saturation_enabled", 0));
  OK(eoir_get_bool(e, "Sensor1", "saturation_enabled", &b));
  CHECK(b == 0);
  FAILS(eoir_get_bool(e, "Sensor1", "f_number", &b), EOIR_ERR_TYPE_MISMATCH, "f_number");
  FAILS(eoir_set_integer(e, "Sensor1", "psf_grid_size", 300), EOIR_ERR_OUT_OF_RANGE, "psf_grid_size");

  /* property enumeration */
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  OK(eoir_property_info_at(e, "Sensor1", 0, &info));
  CHECK(strcmp(info.name, "horizontal_pixels") == 0 && info.type == EOIR_TYPE_INTEGER);
  FAILS(eoir_property_info_at(e, "Sensor1", 999, &info), EOIR_ERR_OUT_OF_RANGE, "index");
  /* 1.3: ranges, closed sets, the fidelity flag; the 1.2 struct size still works */
  CHECK(info.minimum == 0.0 && (info.range_open & 1u) && info.maximum == 16384.0 && !(info.range_open & 2u));
  CHECK(strcmp(info.choices, "") == 0 && info.flags == 0);
  {
    size_t i;
    int seen_quality = 0, seen_samples = 0;
    for (i = 0; eoir_property_info_at(e, "Sensor1", i, &info) == EOIR_OK; ++i) {
      if (strcmp(info.name, "image_quality") == 0)
        seen_quality = strncmp(info.choices, "diffraction_limited,negligible,", 31) == 0 && info.minimum < -1e308;
      if (strcmp(info.name, "samples_per_pixel") == 0)
        seen_samples = (info.flags & EOIR_PROPERTY_FIDELITY) && info.minimum == 1.0 && info.maximum == 16.0;
    }
    CHECK(seen_quality && seen_samples);
    memset(&info, 0x5a, sizeof info);
    info.struct_size = (uint32_t)offsetof(eoir_property_info, flags);
    OK(eoir_property_info_at(e, "Sensor1", 0, &info));
    CHECK(strcmp(info.name, "horizontal_pixels") == 0 && info.flags == 0x5a5a5a5au); /* not written */
  }
  eoir_engine_destroy(e);
  return CHECK_SUMMARY();
}
