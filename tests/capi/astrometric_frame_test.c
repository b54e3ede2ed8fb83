/* A frame's sky coordinates, times and detector values through the C ABI
 * (issue 21 items 1 and 2; C ABI 1.6), C99.
 *
 * - Astrometric places: catalogue stars without proper motion and parallax
 *   have the catalogue's ICRS place as their astrometric place (SOFA,
 *   "Astrometry Tools": astrometric = catalogue place moved by space motion
 *   and parallax, before light deflection and aberration), so the truth's
 *   astrometric RA/Dec must be the CSV's values (1e-9 deg: the inverse of the
 *   apparent-place chain converges to 1e-15 rad); their apparent places lie
 *   1"-23" away (aberration by at most (30.3 + 3.1) km/s / c = 23").
 * - The image's astrometric TAN WCS maps each star's astrometric place to its
 *   truth pixel within 1e-3 pixel (a linear CD matrix about the centre differs
 *   from TAN composed with aberration by (v/c) theta^2: 5e-5 pixel here).
 * - A satellite in the field: geometric and apparent directions are the
 *   direction between the pushed positions (satellites are drawn at their
 *   geometric direction); its astrometric place moves over the integration
 *   by its motion relative to the sensor (constant-velocity extrapolation of
 *   the pushed states, eoir.h): the start-to-end arc equals the geometric
 *   one within 1e-3.
 * - Times: start and end are the frame time -/+ half the integration time;
 *   the observer's state is eoir_object_get_state's; the detector values are
 *   SEI and dark NEI times the peak irradiance responsivity (spec 5.11.4-5,
 *   eqs. 45, 43; the data providers), 0 when saturation or noise is off.
 * - Versioned structs: a 1.5 caller's eoir_image_info and eoir_truth are
 *   filled up to their size and not beyond; a struct_size below 1.1's is
 *   EOIR_ERR_STRUCT_SIZE naming info_out.
 * - display_stretch (issue 21 item 6) takes linear, log, asinh, zscale and
 *   refuses other names, naming the property. */
#include <stddef.h>
#include <unistd.h>

#include "check.h"

static const double kRad = 3.14159265358979323846 / 180.0;

static void unit(double ra_deg, double dec_deg, double out[3]) {
  out[0] = cos(dec_deg * kRad) * cos(ra_deg * kRad);
  out[1] = cos(dec_deg * kRad) * sin(ra_deg * kRad);
  out[2] = sin(dec_deg * kRad);
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Angle between two directions given as RA/Dec (arcsec). */
static double separation_arcsec(double ra1, double dec1, double ra2, double dec2) {
  double a[3], b[3], c[3];
  unit(ra1, dec1, a);
  unit(ra2, dec2, b);
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
  return atan2(sqrt(dot3(c, c)), dot3(a, b)) / kRad * 3600.0;
}

/* Body -> J2000 quaternion {w, x, y, z} of the rotation whose columns are
 * x = y cross z, y (north at the boresight), z (the boresight). */
static void pointing(double ra_deg, double dec_deg, double q[4]) {
  double z[3], y[3], x[3], m[3][3];
  int i;
  unit(ra_deg, dec_deg, z);
  y[0] = -sin(dec_deg * kRad) * cos(ra_deg * kRad);
  y[1] = -sin(dec_deg * kRad) * sin(ra_deg * kRad);
  y[2] = cos(dec_deg * kRad);
  x[0] = y[1] * z[2] - y[2] * z[1];
  x[1] = y[2] * z[0] - y[0] * z[2];
  x[2] = y[0] * z[1] - y[1] * z[0];
  for (i = 0; i < 3; ++i) {
    m[i][0] = x[i];
    m[i][1] = y[i];
    m[i][2] = z[i];
  }
  q[0] = sqrt(1.0 + m[0][0] + m[1][1] + m[2][2]) / 2.0;
  q[1] = (m[2][1] - m[1][2]) / (4.0 * q[0]);
  q[2] = (m[0][2] - m[2][0]) / (4.0 * q[0]);
  q[3] = (m[1][0] - m[0][1]) / (4.0 * q[0]);
}

/* Pixel (0-based column, row from the top) of an RA/Dec through the image's
 * astrometric WCS: gnomonic standard coordinates about the centre, then the
 * inverse of the CD matrix. */
static void wcs_pixel(const eoir_image_info* in, double ra, double dec, double* column, double* row) {
  double c[3], q[3], east[3], north[3], xi, eta, det;
  const double* cd = in->astrometric_cd_deg;
  unit(in->astrometric_ra_deg, in->astrometric_dec_deg, c);
  unit(ra, dec, q);
  east[0] = -sin(in->astrometric_ra_deg * kRad);
  east[1] = cos(in->astrometric_ra_deg * kRad);
  east[2] = 0;
  north[0] = c[1] * east[2] - c[2] * east[1];
  north[1] = c[2] * east[0] - c[0] * east[2];
  north[2] = c[0] * east[1] - c[1] * east[0];
  xi = dot3(q, east) / dot3(q, c) / kRad;
  eta = dot3(q, north) / dot3(q, c) / kRad;
  det = cd[0] * cd[3] - cd[1] * cd[2];
  *column = 0.5 * (in->width - 1) + (cd[3] * xi - cd[1] * eta) / det;
  *row = 0.5 * (in->height - 1) + (-cd[2] * xi + cd[0] * eta) / det;
}

static double provider(eoir_engine e, const char* element) {
  double v = 0;
  OK(eoir_provider_get(e, "EOIR Radiometric Performance", element, "Cam", NULL, &v));
  return v;
}

int main(void) {
  eoir_engine e = NULL;
  char dir[4096], path[4200], rows[2048];
  const double ra0 = 60.0, dec0 = 20.0, integration_s = 0.5;
  const double stars[5][2] = {{60.0, 20.0}, {60.5, 20.2}, {59.4, 19.7}, {60.3, 19.5}, {59.8, 20.6}};
  eoir_time t;
  eoir_state host, sat, host_ef;
  eoir_image_info info, scene;
  double q[4];
  size_t n = 0, i;
  int k, found_stars = 0, found_sat = 0;

  snprintf(dir, sizeof dir, "%s/eoir_astrometric_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (mkdtemp(dir) == NULL) return perror("mkdtemp"), 2;
  snprintf(path, sizeof path, "%s/stars.csv", dir);
  {
    int len = snprintf(rows, sizeof rows, "id,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,parallax_mas,v_mag,b_v\n");
    for (k = 0; k < 5; ++k)
      len += snprintf(rows + len, sizeof rows - (size_t)len, "s%d,%.9f,%.9f,0,0,0,6,0.6\n", k, stars[k][0], stars[k][1]);
    write_text(path, rows);
  }

  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2026-03-20T06:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  OK(eoir_set_string(e, "Stars", "catalog_file", path));
  OK(eoir_set_bool(e, "Stars", "background_light", 0));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Host"));
  OK(eoir_set_string(e, "Host", "shape", "none"));
  /* A GEO host moving at 3.07 km/s, pointing at (60, +20) with north up. */
  host = state_at(EOIR_FRAME_J2000, 4.2164e7, 0, 0);
  host.velocity[1] = 3074.7;
  pointing(ra0, dec0, q);
  for (k = 0; k < 4; ++k) host.attitude[k] = q[k];
  OK(eoir_object_set_state(e, "Host", NULL, &host));
  OK(eoir_sensor_add(e, "Cam", "Host"));
  OK(eoir_set_integer(e, "Cam", "horizontal_pixels", 128));
  OK(eoir_set_integer(e, "Cam", "vertical_pixels", 128));
  OK(eoir_set_number(e, "Cam", "horizontal_fov_deg", 2.0));
  OK(eoir_set_number(e, "Cam", "vertical_fov_deg", 2.0));
  OK(eoir_set_number(e, "Cam", "band_low_um", 0.5));
  OK(eoir_set_number(e, "Cam", "band_high_um", 0.9));
  OK(eoir_set_number(e, "Cam", "f_number", 4.0));
  OK(eoir_set_number(e, "Cam", "focal_length_cm", 20.0));
  OK(eoir_set_number(e, "Cam", "diffraction_wavelength_um", 0.7));
  OK(eoir_set_number(e, "Cam", "integration_time_ms", 1e3 * integration_s));
  /* A satellite 1000 km away, 0.3 deg from the boresight, drifting at
   * 150 m/s across the line of sight. */
  {
    double d[3], u[3];
    unit(60.3, 20.1, d);
    unit(150.0, 0.0, u); /* a direction with a component across the line of sight */
    sat = state_at(EOIR_FRAME_J2000, host.position[0] + 1e6 * d[0], host.position[1] + 1e6 * d[1],
                   host.position[2] + 1e6 * d[2]);
    for (k = 0; k < 3; ++k) sat.velocity[k] = host.velocity[k] + 150.0 * u[k];
  }
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_set_string(e, "Sat", "shape", "sphere"));
  OK(eoir_object_set_state(e, "Sat", NULL, &sat));
  OK(eoir_render(e, "Cam"));

  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  OK(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, &info));
  memset(&scene, 0, sizeof scene);
  scene.struct_size = sizeof scene;
  OK(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SCENE_RADIANCE, &scene));

  /* Times: the integration's start and end about the frame time. */
  NEAR_ABS((info.start_jd_utc[0] - info.time_jd_utc[0]) + (info.start_jd_utc[1] - info.time_jd_utc[1]),
           -0.5 * integration_s / 86400.0, 2e-10);
  NEAR_ABS((info.end_jd_utc[0] - info.time_jd_utc[0]) + (info.end_jd_utc[1] - info.time_jd_utc[1]),
           0.5 * integration_s / 86400.0, 2e-10);
  /* The observer: the host's state (the sensor takes its parent's position). */
  host_ef = state_at(EOIR_FRAME_EARTH_FIXED, 0, 0, 0);
  OK(eoir_object_get_state(e, "Host", &host_ef));
  for (k = 0; k < 3; ++k) {
    NEAR_ABS(info.observer_position_m[k], host.position[k], 1e-6);
    NEAR_ABS(info.observer_velocity_m_s[k], host.velocity[k], 1e-9);
    NEAR_ABS(info.observer_earth_fixed_m[k], host_ef.position[k], 1e-3);
  }
  /* Detector values (the defaults: saturation on, noise on). */
  NEAR_REL(info.saturation_electrons, provider(e, "SEI") * provider(e, "Peak Irradiance Responsivity"), 1e-12);
  NEAR_REL(info.read_noise_electrons, provider(e, "Dark NEI") * provider(e, "Peak Irradiance Responsivity"), 1e-12);
  CHECK(info.saturation_electrons > 0 && info.read_noise_electrons > 0);

  /* The WCS: centred near the boresight (aberration: < 23"), square pixels
   * of 2 tan(1 deg) / 128 rad (1e-4: the field's differential aberration),
   * north up and east left; the scene's CD is the sensor's over 4. */
  CHECK(separation_arcsec(info.astrometric_ra_deg, info.astrometric_dec_deg, ra0, dec0) < 23.0);
  NEAR_REL(sqrt(fabs(info.astrometric_cd_deg[0] * info.astrometric_cd_deg[3] -
                     info.astrometric_cd_deg[1] * info.astrometric_cd_deg[2])),
           2.0 * tan(1.0 * kRad) / 128.0 / kRad, 1.2e-4);
  CHECK(info.astrometric_cd_deg[0] < 0 && info.astrometric_cd_deg[3] < 0);
  CHECK(fabs(info.astrometric_cd_deg[1]) < 1e-3 * fabs(info.astrometric_cd_deg[0]));
  for (k = 0; k < 4; ++k) NEAR_REL(scene.astrometric_cd_deg[k] * 4.0, info.astrometric_cd_deg[k], 1e-12);
  NEAR_ABS(scene.astrometric_ra_deg, info.astrometric_ra_deg, 0.0);

  OK(eoir_truth_count(e, "Cam", &n));
  for (i = 0; i < n; ++i) {
    eoir_truth tr;
    double column = 0, row = 0;
    memset(&tr, 0, sizeof tr);
    tr.struct_size = sizeof tr;
    OK(eoir_truth_get(e, "Cam", i, &tr));
    wcs_pixel(&info, tr.astrometric_ra_deg, tr.astrometric_dec_deg, &column, &row);
    NEAR_ABS(column, tr.pixel_x, 1e-3);
    NEAR_ABS(row, tr.pixel_y, 1e-3);
    if (tr.kind == EOIR_TRUTH_STAR) {
      const int s = tr.object[1] - '0';
      ++found_stars;
      NEAR_ABS(tr.astrometric_ra_deg, stars[s][0], 1e-9);
      NEAR_ABS(tr.astrometric_dec_deg, stars[s][1], 1e-9);
      NEAR_ABS(tr.geometric_ra_deg, stars[s][0], 1e-9);
      NEAR_ABS(tr.geometric_dec_deg, stars[s][1], 1e-9);
      NEAR_ABS(tr.start_astrometric_ra_deg, tr.astrometric_ra_deg, 0.0);
      NEAR_ABS(tr.end_astrometric_dec_deg, tr.astrometric_dec_deg, 0.0);
      {
        const double aberration = separation_arcsec(tr.right_ascension_deg, tr.declination_deg,
                                                    tr.astrometric_ra_deg, tr.astrometric_dec_deg);
        CHECK(aberration > 1.0 && aberration < 23.0);
      }
    } else if (strcmp(tr.object, "Sat") == 0) {
      double d[3], ra, dec, arc_geo, arc, start[3], end[3];
      ++found_sat;
      for (k = 0; k < 3; ++k) d[k] = sat.position[k] - host.position[k];
      ra = atan2(d[1], d[0]) / kRad;
      dec = asin(d[2] / sqrt(dot3(d, d))) / kRad;
      NEAR_ABS(separation_arcsec(tr.geometric_ra_deg, tr.geometric_dec_deg, ra, dec), 0.0, 1e-6);
      NEAR_ABS(separation_arcsec(tr.right_ascension_deg, tr.declination_deg, ra, dec), 0.0, 1e-6);
      CHECK(separation_arcsec(tr.astrometric_ra_deg, tr.astrometric_dec_deg, ra, dec) > 1.0);
      /* Over the integration: start and end straddle the middle. */
      for (k = 0; k < 3; ++k) {
        start[k] = d[k] - 0.5 * integration_s * (sat.velocity[k] - host.velocity[k]);
        end[k] = d[k] + 0.5 * integration_s * (sat.velocity[k] - host.velocity[k]);
      }
      arc_geo = acos(dot3(start, end) / sqrt(dot3(start, start) * dot3(end, end))) / kRad * 3600.0;
      arc = separation_arcsec(tr.start_astrometric_ra_deg, tr.start_astrometric_dec_deg, tr.end_astrometric_ra_deg,
                              tr.end_astrometric_dec_deg);
      CHECK(arc_geo > 5.0);
      NEAR_REL(arc, arc_geo, 1e-3);
      NEAR_REL(separation_arcsec(tr.start_astrometric_ra_deg, tr.start_astrometric_dec_deg, tr.astrometric_ra_deg,
                                 tr.astrometric_dec_deg),
               0.5 * arc_geo, 2e-3);
    }
  }
  CHECK(found_stars == 5);
  CHECK(found_sat == 1);

  /* A 1.5 caller: filled up to its struct_size, nothing beyond. */
  {
    unsigned char buf[sizeof(eoir_image_info) + 16];
    eoir_image_info* old = (eoir_image_info*)(void*)buf;
    size_t b;
    int untouched = 1;
    memset(buf, 0xAB, sizeof buf);
    old->struct_size = (uint32_t)offsetof(eoir_image_info, start_jd_utc);
    OK(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, old));
    CHECK(old->width == 128 && old->up_dec_deg == info.up_dec_deg);
    for (b = offsetof(eoir_image_info, start_jd_utc); b < sizeof buf; ++b) untouched &= buf[b] == 0xAB;
    CHECK(untouched);
    old->struct_size = 8;
    FAILS(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, old), EOIR_ERR_STRUCT_SIZE, "info_out");
  }
  {
    unsigned char buf[sizeof(eoir_truth) + 16];
    eoir_truth* old = (eoir_truth*)(void*)buf;
    size_t b;
    int untouched = 1;
    memset(buf, 0xAB, sizeof buf);
    old->struct_size = (uint32_t)offsetof(eoir_truth, astrometric_ra_deg);
    OK(eoir_truth_get(e, "Cam", 0, old));
    for (b = offsetof(eoir_truth, astrometric_ra_deg); b < sizeof buf; ++b) untouched &= buf[b] == 0xAB;
    CHECK(untouched);
  }

  /* Saturation and noise off: 0. */
  OK(eoir_set_bool(e, "Cam", "saturation_enabled", 0));
  OK(eoir_set_bool(e, "Cam", "noise_enabled", 0));
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SENSOR_ELECTRONS, &info));
  CHECK(info.saturation_electrons == 0.0 && info.read_noise_electrons == 0.0);

  /* The display stretch: four names, others refused naming the property. */
  {
    const char* names[4] = {"linear", "log", "asinh", "zscale"};
    char got[16];
    for (k = 0; k < 4; ++k) {
      OK(eoir_set_string(e, "Cam", "display_stretch", names[k]));
      OK(eoir_get_string(e, "Cam", "display_stretch", got, sizeof got));
      CHECK(strcmp(got, names[k]) == 0);
    }
    FAILS(eoir_set_string(e, "Cam", "display_stretch", "sqrt"), EOIR_ERR_UNKNOWN_NAME, "display_stretch");
    OK(eoir_render(e, "Cam"));
  }

  eoir_engine_destroy(e);
  unlink(path);
  rmdir(dir);
  return CHECK_SUMMARY();
}
