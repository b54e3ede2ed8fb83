/* C ABI: what a sensor on the ground sees through the Earth's atmosphere
 * (issue 20 item 6; spec 4.3.1.1, 6.2.5.4), C99. A site at sea level (0 N,
 * 0 E: the US76 ground, 1013.25 hPa and 288.15 K) looks north at a
 * satellite beyond the atmosphere and at a star of a user catalogue:
 *
 * - truth's air mass is Kasten and Young (1989) of the apparent zenith
 *   angle within 1 %, for the satellite and for the star;
 * - the satellite's and the star's truth pixels move up the picture (toward
 *   the zenith) by the refraction R, and the satellite's image with them
 *   (centroid on the truth pixel, 0.05 px): at 10 deg (the satellite) and
 *   12 deg (the star) within 5 % of Bennett's (1982) R = cot(h + 7.31 / (h + 4.4))
 *   arcmin at the apparent altitude h deg, scaled by (P / 1010 hPa)
 *   (283 K / T); at 45 deg within 2" of 58" (ERFA's A tan z, which the
 *   engine uses there);
 * - a satellite climbing through 10 deg during a 2 s integration streaks
 *   longer by the change of R between its ends (Bennett, 10 %);
 * - an extended satellite's whole image moves up by R as well (Bennett, 5 %);
 * - an aircraft 20 km away at 0.5 deg moves up by the terrestrial
 *   refraction k D / (2 R_E) (5 %);
 * - with the atmosphere off the air mass is 0 and nothing moves;
 * - a caller of the struct before air_mass gets nothing written there. */
#define _XOPEN_SOURCE 700
#include <stddef.h>
#include <stdlib.h>
#include <unistd.h>

#include "check.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
#define PIXELS 128
#define FOV_DEG 0.5
#define CENTRE ((PIXELS - 1) / 2.0) /* pixel 0 is centred on 0 */
#define RANGE_M 3.0e6               /* the satellite: 1100 km up at 10 deg */


/* Bennett (1982) for the US76 ground: the refraction (deg) of a source at
 * true elevation e_deg, h = e + R(h) by fixed-point iteration. */
static double bennett_deg(double e_deg) {
  const double scale = (1013.25 / 1010.0) * (283.0 / 288.15);
  double h = e_deg;
  int i;
  for (i = 0; i < 50; ++i) h = e_deg + scale / tan((h + 7.31 / (h + 4.4)) * DEG) / 60.0;
  return h - e_deg;
}

/* The angle (deg) between the boresight and a point `rows` pixels above the
 * centre of the picture (the tangent-plane grid of FOV_DEG over PIXELS). */
static double angle_up_deg(double rows) {
  return atan(rows * 2.0 * tan(0.5 * FOV_DEG * DEG) / PIXELS) / DEG;
}

/* Earth, the site "Obs" at sea level at 0 N 0 E, its sensor "Scope"
 * (PIXELS^2 over FOV_DEG, 0.5-0.9 um: refraction is computed for visible
 * light; noise and saturation off, jitter) pointed north at elevation
 * el_deg, and the satellite "Sat" (the default sphere at 2000 K: it glows in the
 * band by night). */
static eoir_engine observatory(double el_deg, int atmosphere) {
  eoir_engine e = NULL;
  eoir_time t;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T04:00:00Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_set_string(e, "Earth", "atmosphere", atmosphere ? "simple" : "none"));
  OK(eoir_object_add(e, EOIR_KIND_SITE, "Obs"));
  OK(eoir_set_number(e, "Obs", "latitude_deg", 0.0));
  OK(eoir_set_number(e, "Obs", "longitude_deg", 0.0));
  OK(eoir_set_number(e, "Obs", "height_m", 0.0));
  OK(eoir_sensor_add(e, "Scope", "Obs"));
  OK(eoir_set_integer(e, "Scope", "horizontal_pixels", PIXELS));
  OK(eoir_set_integer(e, "Scope", "vertical_pixels", PIXELS));
  OK(eoir_set_number(e, "Scope", "horizontal_fov_deg", FOV_DEG));
  OK(eoir_set_number(e, "Scope", "vertical_fov_deg", FOV_DEG));
  OK(eoir_set_number(e, "Scope", "band_low_um", 0.5));
  OK(eoir_set_number(e, "Scope", "band_high_um", 0.9));
  OK(eoir_set_bool(e, "Scope", "noise_enabled", 0));
  OK(eoir_set_bool(e, "Scope", "saturation_enabled", 0));
  OK(eoir_set_number(e, "Scope", "jitter_mrad", 0.1)); /* a PSF of 1.5 px sigma: centroids */
  OK(eoir_sensor_point_azel(e, "Scope", 0.0, el_deg));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_set_number(e, "Sat", "temperature_K", 2000.0));
  OK(place_north(e, "Sat", 0.0, RANGE_M, el_deg));
  return e;
}

/* The truth row of `object` in the last frame of Scope; 0 if absent. */
static int truth_of(eoir_engine e, const char* object, eoir_truth* out) {
  size_t n = 0, i;
  OK(eoir_truth_count(e, "Scope", &n));
  for (i = 0; i < n; ++i) {
    memset(out, 0, sizeof *out);
    out->struct_size = sizeof *out;
    OK(eoir_truth_get(e, "Scope", i, out));
    if (strcmp(out->object, object) == 0) return 1;
  }
  return 0;
}

/* The centroid of the noise-free electrons within 6 pixels of (x, y), above
 * the window's least value. */
static void centroid(eoir_engine e, double x, double y, double* cx, double* cy) {
  static double v[PIXELS * PIXELS];
  double sum = 0, sx = 0, sy = 0, least = INFINITY;
  int i, j;
  const int x0 = (int)floor(x + 0.5), y0 = (int)floor(y + 0.5);
  OK(eoir_image_get(e, "Scope", EOIR_IMAGE_SENSOR_MEAN, v, PIXELS * PIXELS));
  for (j = y0 - 6; j <= y0 + 6; ++j)
    for (i = x0 - 6; i <= x0 + 6; ++i)
      if (i >= 0 && j >= 0 && i < PIXELS && j < PIXELS && v[j * PIXELS + i] < least) least = v[j * PIXELS + i];
  for (j = y0 - 6; j <= y0 + 6; ++j)
    for (i = x0 - 6; i <= x0 + 6; ++i) {
      double w;
      if (i < 0 || j < 0 || i >= PIXELS || j >= PIXELS) continue;
      w = v[j * PIXELS + i] - least;
      sum += w, sx += w * i, sy += w * j;
    }
  *cx = sum > 0 ? sx / sum : -1;
  *cy = sum > 0 ? sy / sum : -1;
}

/* The satellite at el_deg: off, then on. Returns the refraction seen (deg). */
static double satellite_at(double el_deg) {
  eoir_engine e = observatory(el_deg, 0);
  eoir_truth off, on;
  double cx, cy, seen;
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Sat", &off));
  /* Vacuum: no air, the satellite where the pointing puts it. */
  CHECK(off.air_mass == 0.0);
  NEAR_ABS(off.pixel_x, CENTRE, 0.01);
  NEAR_ABS(off.pixel_y, CENTRE, 0.01);
  NEAR_ABS(off.elevation_deg, el_deg, 1e-6);
  CHECK(off.point_source == 1);
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Sat", &on));
  /* Straight up the picture (north, pointed north), by R. */
  NEAR_ABS(on.pixel_x, off.pixel_x, 0.01);
  seen = angle_up_deg(CENTRE - on.pixel_y) - angle_up_deg(CENTRE - off.pixel_y);
  /* The directions stay geometric. */
  CHECK(on.elevation_deg == off.elevation_deg && on.right_ascension_deg == off.right_ascension_deg);
  NEAR_REL(on.air_mass, kasten_young(90.0 - el_deg - bennett_deg(el_deg)), 0.01);
  /* The image has the satellite where truth says. */
  centroid(e, on.pixel_x, on.pixel_y, &cx, &cy);
  NEAR_ABS(cx, on.pixel_x, 0.05);
  NEAR_ABS(cy, on.pixel_y, 0.05);
  printf("satellite at %g deg: refraction %.2f\" (Bennett %.2f\"), %.2f px; air mass %.5f (Kasten-Young %.5f); "
         "image centroid (%.3f, %.3f), truth (%.3f, %.3f)\n",
         el_deg, seen * 3600, bennett_deg(el_deg) * 3600, off.pixel_y - on.pixel_y, on.air_mass,
         kasten_young(90.0 - el_deg - bennett_deg(el_deg)), cx, cy, on.pixel_x, on.pixel_y);
  /* A caller of the struct before air_mass gets nothing written there. */
  {
    eoir_truth old;
    memset(&old, 0x5a, sizeof old);
    old.struct_size = (uint32_t)offsetof(eoir_truth, air_mass);
    OK(eoir_truth_get(e, "Scope", 0, &old));
    CHECK(strcmp(old.object, "Sat") == 0 && old.elevation_deg == on.elevation_deg);
    {
      eoir_truth pattern;
      memset(&pattern, 0x5a, sizeof pattern);
      CHECK(memcmp(&old.air_mass, &pattern.air_mass, sizeof old.air_mass) == 0);
    }
  }
  eoir_engine_destroy(e);
  return seen;
}

/* A satellite climbing at 7 km/s across the line of sight through 10 deg
 * during a 2 s integration: its streak's ends are refracted as their own
 * elevations ask, so with the atmosphere on the streak grows by
 * R(start) - R(end) (Bennett, 10 %). */
static void streak_ends(void) {
  const double el = 10.0, speed = 7000.0, half_s = 1.0;
  const double lift_deg = atan(speed * half_s / RANGE_M) / DEG;
  eoir_engine e = observatory(el, 0);
  eoir_truth off, on;
  eoir_state s;
  double grown, expected;
  OK(eoir_set_number(e, "Scope", "integration_time_ms", 2000.0 * half_s));
  /* Earth-fixed velocity along the local vertical plane, perpendicular to the
   * line of sight (up in the picture). */
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_EARTH_FIXED;
  s.position[0] = 6378137.0 + RANGE_M * sin(el * DEG);
  s.position[2] = RANGE_M * cos(el * DEG);
  s.velocity[0] = speed * cos(el * DEG);
  s.velocity[2] = -speed * sin(el * DEG);
  s.attitude[0] = 1;
  OK(eoir_object_set_state(e, "Sat", NULL, &s));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Sat", &off));
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Sat", &on));
  /* The streak runs up the picture (rows fall), about 2 x lift_deg long. */
  NEAR_ABS(angle_up_deg(CENTRE - off.end_pixel_y) - angle_up_deg(CENTRE - off.start_pixel_y), 2 * lift_deg,
           0.02 * lift_deg);
  grown = (angle_up_deg(CENTRE - off.start_pixel_y) - angle_up_deg(CENTRE - on.start_pixel_y)) -
          (angle_up_deg(CENTRE - off.end_pixel_y) - angle_up_deg(CENTRE - on.end_pixel_y));
  expected = bennett_deg(el - lift_deg) - bennett_deg(el + lift_deg);
  printf("streak through %g deg over %.3f deg: the ends' refraction differs by %.3f\" (Bennett %.3f\")\n", el,
         2 * lift_deg, -grown * 3600, expected * 3600);
  NEAR_REL(-grown, expected, 0.10);
  eoir_engine_destroy(e);
}

/* A star of a user catalogue at the boresight, pointed north at 12 deg: its
 * air mass follows Kasten and Young of its apparent zenith angle (1 %) and
 * it moves up by R (5 %), as the satellite does. */
static void star_at_12_deg(void) {
  char dir[4096], path[4200], text[512];
  eoir_engine e = observatory(12.0, 0);
  eoir_image_info info;
  eoir_truth off, on;
  double seen;
  snprintf(dir, sizeof dir, "%s/eoir_site_refraction_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (mkdtemp(dir) == NULL) {
    perror("mkdtemp");
    exit(2);
  }
  snprintf(path, sizeof path, "%s/star.csv", dir);
  OK(eoir_object_remove(e, "Sat"));
  OK(eoir_render(e, "Scope"));
  memset(&info, 0, sizeof info);
  info.struct_size = sizeof info;
  OK(eoir_image_info_get(e, "Scope", EOIR_IMAGE_SENSOR_MEAN, &info));
  snprintf(text, sizeof text, "id,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,parallax_mas,v_mag,b_v\nS,%.9f,%.9f,0,0,0,5,0.6\n",
           info.boresight_ra_deg, info.boresight_dec_deg);
  write_text(path, text);
  OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  OK(eoir_set_string(e, "Stars", "catalog_file", path));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "S", &off));
  CHECK(off.kind == EOIR_TRUTH_STAR && off.air_mass == 0.0);
  /* At the boresight but for its aberration (< 21"). */
  NEAR_ABS(off.elevation_deg, 12.0, 0.01);
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "S", &on));
  NEAR_REL(on.air_mass, kasten_young(90.0 - on.elevation_deg - bennett_deg(on.elevation_deg)), 0.01);
  NEAR_ABS(on.pixel_x, off.pixel_x, 0.01);
  seen = angle_up_deg(CENTRE - on.pixel_y) - angle_up_deg(CENTRE - off.pixel_y);
  NEAR_REL(seen, bennett_deg(on.elevation_deg), 0.05);
  CHECK(on.right_ascension_deg == off.right_ascension_deg && on.declination_deg == off.declination_deg);
  printf("star at %.4f deg: refraction %.2f\" (Bennett %.2f\"); air mass %.5f (Kasten-Young %.5f)\n",
         on.elevation_deg, seen * 3600, bennett_deg(on.elevation_deg) * 3600, on.air_mass,
         kasten_young(90.0 - on.elevation_deg - bennett_deg(on.elevation_deg)));
  eoir_engine_destroy(e);
  remove(path);
  rmdir(dir);
}

/* The centroid of the noise-free electrons of the whole picture above its
 * least value. */
static void whole_centroid(eoir_engine e, double* cx, double* cy) {
  static double v[PIXELS * PIXELS];
  double sum = 0, sx = 0, sy = 0, least = INFINITY;
  int i;
  OK(eoir_image_get(e, "Scope", EOIR_IMAGE_SENSOR_MEAN, v, PIXELS * PIXELS));
  for (i = 0; i < PIXELS * PIXELS; ++i)
    if (v[i] < least) least = v[i];
  for (i = 0; i < PIXELS * PIXELS; ++i) {
    const double w = v[i] - least;
    sum += w, sx += w * (i % PIXELS), sy += w * (i / PIXELS);
  }
  *cx = sum > 0 ? sx / sum : -1;
  *cy = sum > 0 ? sy / sum : -1;
}

/* An extended satellite (a sphere 3 km in radius, 0.115 deg or 29 pixels
 * across, 3000 km away at 10 deg): the ray caster meets it where the
 * refraction puts it, so its image's centroid moves up by R as the point
 * source's does (Bennett, 5 %). */
static void extended_at_10_deg(void) {
  eoir_engine e = observatory(10.0, 0);
  const double radius = 3000.0;
  double x0, y0, x1, y1, seen;
  OK(eoir_set_array(e, "Sat", "dimensions_m", &radius, 1));
  OK(eoir_render(e, "Scope"));
  whole_centroid(e, &x0, &y0);
  NEAR_ABS(y0, CENTRE, 0.05);
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  OK(eoir_render(e, "Scope"));
  whole_centroid(e, &x1, &y1);
  NEAR_ABS(x1, x0, 0.05);
  seen = angle_up_deg(CENTRE - y1) - angle_up_deg(CENTRE - y0);
  NEAR_REL(seen, bennett_deg(10.0), 0.05);
  printf("extended satellite at 10 deg: its image moved up %.2f\" (Bennett %.2f\")\n", seen * 3600,
         bennett_deg(10.0) * 3600);
  eoir_engine_destroy(e);
}

/* An aircraft 20 km away at 0.5 deg, inside the atmosphere: seen above its
 * place by the terrestrial refraction k D / (2 R_E), the geodetic
 * coefficient of refraction k = 503 P / T^2 (0.0343 + dT/dh) of the US76
 * ground (1013.25 hPa, 288.15 K, -0.0065 K/m: 0.171), within 5 %, far less
 * than a star's 29' there. */
static void aircraft_at_half_degree(void) {
  eoir_engine e = observatory(0.5, 0);
  eoir_truth off, on;
  const double D = 20000.0, k = 503.0 * 1013.25 / (288.15 * 288.15) * (0.0343 - 0.0065);
  double seen;
  OK(eoir_object_remove(e, "Sat"));
  OK(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Plane"));
  OK(eoir_set_number(e, "Plane", "temperature_K", 2000.0));
  OK(place_north(e, "Plane", 0.0, D, 0.5));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Plane", &off));
  OK(eoir_set_string(e, "Earth", "atmosphere", "simple"));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Plane", &on));
  NEAR_ABS(on.pixel_x, off.pixel_x, 0.01);
  seen = angle_up_deg(CENTRE - on.pixel_y) - angle_up_deg(CENTRE - off.pixel_y);
  NEAR_REL(seen * PI / 180.0, k * D / (2.0 * 6378137.0), 0.05);
  printf("aircraft 20 km away at 0.5 deg: raised %.2f\" (k D / 2 R_E %.2f\")\n", seen * 3600,
         k * D / (2.0 * 6378137.0) * 180.0 / PI * 3600);
  eoir_engine_destroy(e);
}

int main(void) {
  NEAR_REL(satellite_at(10.0), bennett_deg(10.0), 0.05);
  NEAR_ABS(satellite_at(45.0) * 3600.0, 58.0, 2.0);
  streak_ends();
  star_at_12_deg();
  extended_at_10_deg();
  aircraft_at_half_degree();
  return CHECK_SUMMARY();
}
