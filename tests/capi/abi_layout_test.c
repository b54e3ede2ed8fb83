/* The C ABI is a promise (house rule 6): the layout of every public struct
 * of ABI v1 on LP64 (x86_64) as released. Fields are only ever appended, so
 * these offsets never change; a struct may only grow. A failure here means
 * the header broke binary compatibility. */
#include <stddef.h>

#include "check.h"

#define CHECK_LAYOUT(T, field, offset)                                                     \
  do {                                                                                     \
    ++check_count;                                                                         \
    if (offsetof(T, field) != (offset)) {                                                  \
      ++check_failures;                                                                    \
      fprintf(stderr, "%s.%s moved: offset %zu, ABI v1 has %zu\n", #T, #field,             \
              offsetof(T, field), (size_t)(offset));                                       \
    }                                                                                      \
  } while (0)
#define CHECK_SIZE(T, size)                                                                \
  do {                                                                                     \
    ++check_count;                                                                         \
    if (sizeof(T) < (size)) {                                                              \
      ++check_failures;                                                                    \
      fprintf(stderr, "%s shrank: %zu bytes, ABI v1 has %zu\n", #T, sizeof(T), (size_t)(size)); \
    }                                                                                      \
  } while (0)

int main(void) {
  if (sizeof(void*) != 8) {
    printf("layout baseline is for LP64; skipped on this platform\n");
    return 0;
  }
  CHECK_SIZE(eoir_engine_desc, 16);
  CHECK_LAYOUT(eoir_engine_desc, threads, 4);
  CHECK_LAYOUT(eoir_engine_desc, seed, 8);
  CHECK_LAYOUT(eoir_engine_desc, data_dir, 16); /* 1.3 */
  CHECK_SIZE(eoir_time, 24);
  CHECK_LAYOUT(eoir_time, jd1, 8);
  CHECK_LAYOUT(eoir_time, jd2, 16);
  CHECK_SIZE(eoir_state, 112);
  CHECK_LAYOUT(eoir_state, angular_velocity, 88); /* 1.3 */
  CHECK_LAYOUT(eoir_state, frame, 4);
  CHECK_LAYOUT(eoir_state, position, 8);
  CHECK_LAYOUT(eoir_state, velocity, 32);
  CHECK_LAYOUT(eoir_state, attitude, 56);
  CHECK_SIZE(eoir_property_info, 72);
  CHECK_LAYOUT(eoir_property_info, name, 8);
  CHECK_LAYOUT(eoir_property_info, type, 16);
  CHECK_LAYOUT(eoir_property_info, unit, 24);
  CHECK_LAYOUT(eoir_property_info, description, 32);
  CHECK_LAYOUT(eoir_property_info, flags, 40); /* 1.3 */
  CHECK_LAYOUT(eoir_property_info, range_open, 44);
  CHECK_LAYOUT(eoir_property_info, minimum, 48);
  CHECK_LAYOUT(eoir_property_info, maximum, 56);
  CHECK_LAYOUT(eoir_property_info, choices, 64);
  CHECK_SIZE(eoir_element_info, 40);
  CHECK_LAYOUT(eoir_element_info, name, 8);
  CHECK_LAYOUT(eoir_element_info, type, 16);
  CHECK_LAYOUT(eoir_element_info, unit, 24);
  CHECK_LAYOUT(eoir_element_info, x_unit, 32);
  CHECK_SIZE(eoir_host_api, 32);
  CHECK_LAYOUT(eoir_host_api, user, 8);
  CHECK_LAYOUT(eoir_host_api, log, 16);
  CHECK_LAYOUT(eoir_host_api, progress, 24);
  CHECK_SIZE(eoir_image_info, 72);
  CHECK_LAYOUT(eoir_image_info, width, 4);
  CHECK_LAYOUT(eoir_image_info, height, 8);
  CHECK_LAYOUT(eoir_image_info, kind, 12);
  CHECK_LAYOUT(eoir_image_info, unit, 16);
  CHECK_LAYOUT(eoir_image_info, time_jd_utc, 24);
  CHECK_LAYOUT(eoir_image_info, boresight_ra_deg, 40);
  CHECK_LAYOUT(eoir_image_info, up_dec_deg, 64);
  CHECK_LAYOUT(eoir_image_info, start_jd_utc, 72); /* 1.6 */
  CHECK_LAYOUT(eoir_image_info, end_jd_utc, 88);
  CHECK_LAYOUT(eoir_image_info, astrometric_ra_deg, 104);
  CHECK_LAYOUT(eoir_image_info, astrometric_cd_deg, 120);
  CHECK_LAYOUT(eoir_image_info, observer_position_m, 152);
  CHECK_LAYOUT(eoir_image_info, observer_velocity_m_s, 176);
  CHECK_LAYOUT(eoir_image_info, observer_earth_fixed_m, 200);
  CHECK_LAYOUT(eoir_image_info, saturation_electrons, 224);
  CHECK_LAYOUT(eoir_image_info, read_noise_electrons, 232);
  CHECK_LAYOUT(eoir_image_info, gain_e_per_adu, 240); /* 1.7 */
  CHECK_LAYOUT(eoir_image_info, bias_adu, 248);
  CHECK_LAYOUT(eoir_image_info, saturation_adu, 256);
  CHECK_LAYOUT(eoir_image_info, adc_max_adu, 264);
  CHECK_SIZE(eoir_pick, 144);
  CHECK_LAYOUT(eoir_pick, hit, 4);
  CHECK_LAYOUT(eoir_pick, object, 8);
  CHECK_LAYOUT(eoir_pick, patch, 72);
  CHECK_LAYOUT(eoir_pick, range_m, 80);
  CHECK_LAYOUT(eoir_pick, has_geodetic, 88);
  CHECK_LAYOUT(eoir_pick, latitude_deg, 96);
  CHECK_LAYOUT(eoir_pick, right_ascension_deg, 112);
  CHECK_LAYOUT(eoir_pick, effective_radiance, 128);
  CHECK_LAYOUT(eoir_pick, temperature_K, 136);
  CHECK_SIZE(eoir_truth, 200);
  CHECK_LAYOUT(eoir_truth, object, 4);
  CHECK_LAYOUT(eoir_truth, pixel_x, 72);
  CHECK_LAYOUT(eoir_truth, range_m, 88);
  CHECK_LAYOUT(eoir_truth, point_source, 96);
  CHECK_LAYOUT(eoir_truth, visible, 100);
  CHECK_LAYOUT(eoir_truth, effective_irradiance, 104);
  CHECK_LAYOUT(eoir_truth, snr, 120);
  CHECK_LAYOUT(eoir_truth, kind, 128); /* 1.3 */
  CHECK_LAYOUT(eoir_truth, right_ascension_deg, 136);
  CHECK_LAYOUT(eoir_truth, v_mag, 152);
  CHECK_LAYOUT(eoir_truth, start_pixel_x, 168);
  CHECK_LAYOUT(eoir_truth, end_pixel_y, 192);
  CHECK_LAYOUT(eoir_truth, topocentric, 200); /* 1.5 */
  CHECK_LAYOUT(eoir_truth, azimuth_deg, 208);
  CHECK_LAYOUT(eoir_truth, elevation_deg, 216);
  CHECK_LAYOUT(eoir_truth, air_mass, 224);
  CHECK_LAYOUT(eoir_truth, astrometric_ra_deg, 232); /* 1.6 */
  CHECK_LAYOUT(eoir_truth, start_astrometric_ra_deg, 248);
  CHECK_LAYOUT(eoir_truth, end_astrometric_dec_deg, 272);
  CHECK_LAYOUT(eoir_truth, geometric_ra_deg, 280);
  CHECK_LAYOUT(eoir_truth, geometric_dec_deg, 288);
  CHECK_LAYOUT(eoir_api_v1, abi_major, 4);
  CHECK_LAYOUT(eoir_api_v1, version, 16);
  CHECK_LAYOUT(eoir_api_v1, engine_create, 40);
  CHECK_LAYOUT(eoir_api_v1, sensor_load, 288);
  CHECK_LAYOUT(eoir_api_v1, render, 296);
  CHECK_LAYOUT(eoir_api_v1, pick_get, 328);
  CHECK_LAYOUT(eoir_api_v1, snr_constraint, 336);
  CHECK_LAYOUT(eoir_api_v1, truth_get, 352);
  CHECK_LAYOUT(eoir_api_v1, frame_fidelity_get, 392); /* 1.4 */
  CHECK_LAYOUT(eoir_api_v1, sensor_point_azel, 400);  /* 1.5 */
  CHECK_LAYOUT(eoir_api_v1, sensor_point_at, 408);
  CHECK_LAYOUT(eoir_api_v1, pick_term_get, 416);  /* 1.6 */
  CHECK_LAYOUT(eoir_api_v1, image_get_adu, 424);  /* 1.7 */
  CHECK_LAYOUT(eoir_api_v1, engine_set_limits, 432); /* 1.7 */
  CHECK_LAYOUT(eoir_api_v1, engine_get_limits, 440);
  CHECK_LAYOUT(eoir_limits, max_satellites, 4); /* 1.7 */
  CHECK_LAYOUT(eoir_limits, max_sensors, 20);
  CHECK_SIZE(eoir_limits, 24);
  return CHECK_SUMMARY();
}
