/* C ABI: sites (issue 20 item 6). A site is fixed on the Earth at a WGS84
 * geodetic position, carries sensors, images nothing, takes no state and
 * counts against EOIR_MAX_SITES, not the vehicle limit. Its sensors point by
 * topocentric azimuth and elevation or track a named object
 * (eoir_sensor_point_azel, eoir_sensor_point_at), and truth gives the
 * topocentric azimuth and elevation of each target.
 *
 * The expected directions are computed here, independently of the engine:
 * WGS84 geodetic to Earth-fixed in closed form (a = 6378137 m, f =
 * 1/298.257223563) and the east-north-up basis of the geodetic normal. */

#include <stddef.h>
#include <stdlib.h>
#include <unistd.h>

#include "check.h"

#define PI 3.14159265358979323846
#define PIXELS 64
#define CENTRE ((PIXELS - 1) / 2.0) /* pixel 0 is centred on 0 */

/* White Sands, New Mexico. */
static const double site_lat = 32.3805, site_lon = -106.4793, site_height = 1224.0;


static void geodetic_to_ecef(double lat_deg, double lon_deg, double h, double r[3]) {
  const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2.0 - f);
  const double p = lat_deg * PI / 180.0, l = lon_deg * PI / 180.0;
  const double n = a / sqrt(1.0 - e2 * sin(p) * sin(p));
  r[0] = (n + h) * cos(p) * cos(l);
  r[1] = (n + h) * cos(p) * sin(l);
  r[2] = (n * (1.0 - e2) + h) * sin(p);
}

/* Earth-fixed unit vectors east, north, up at lat/lon. */
static void enu_basis(double lat_deg, double lon_deg, double east[3], double north[3], double up[3]) {
  const double p = lat_deg * PI / 180.0, l = lon_deg * PI / 180.0;
  east[0] = -sin(l), east[1] = cos(l), east[2] = 0.0;
  north[0] = -sin(p) * cos(l), north[1] = -sin(p) * sin(l), north[2] = cos(p);
  up[0] = cos(p) * cos(l), up[1] = cos(p) * sin(l), up[2] = sin(p);
}

/* Earth-fixed position `range` metres from the site along azimuth/elevation. */
static void place_at_azel(double az_deg, double el_deg, double range, double out[3]) {
  double site[3], e[3], n[3], u[3];
  const double a = az_deg * PI / 180.0, el = el_deg * PI / 180.0;
  int i;
  geodetic_to_ecef(site_lat, site_lon, site_height, site);
  enu_basis(site_lat, site_lon, e, n, u);
  for (i = 0; i < 3; ++i) out[i] = site[i] + range * (cos(el) * sin(a) * e[i] + cos(el) * cos(a) * n[i] + sin(el) * u[i]);
}

static void set_time(eoir_engine e, const char* iso) {
  eoir_time t;
  OK(eoir_time_from_iso(iso, &t));
  OK(eoir_engine_set_time(e, &t));
}

/* Earth, the site "Obs" and its sensor "Scope": PIXELS^2 pixels over 1 deg,
 * visible band, noise off. */
static eoir_engine observatory(void) {
  eoir_engine e = NULL;
  OK(eoir_engine_create(NULL, &e));
  set_time(e, "2010-08-25T04:00:00Z");
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_SITE, "Obs"));
  OK(eoir_set_number(e, "Obs", "latitude_deg", site_lat));
  OK(eoir_set_number(e, "Obs", "longitude_deg", site_lon));
  OK(eoir_set_number(e, "Obs", "height_m", site_height));
  OK(eoir_sensor_add(e, "Scope", "Obs"));
  OK(eoir_set_integer(e, "Scope", "horizontal_pixels", PIXELS));
  OK(eoir_set_integer(e, "Scope", "vertical_pixels", PIXELS));
  OK(eoir_set_number(e, "Scope", "horizontal_fov_deg", 1.0));
  OK(eoir_set_number(e, "Scope", "vertical_fov_deg", 1.0));
  OK(eoir_set_number(e, "Scope", "band_low_um", 0.5));
  OK(eoir_set_number(e, "Scope", "band_high_um", 0.9));
  OK(eoir_set_bool(e, "Scope", "noise_enabled", 0));
  return e;
}

/* The truth row of `object` in the last frame of `sensor`; 0 if absent. */
static int truth_of(eoir_engine e, const char* sensor, const char* object, eoir_truth* out) {
  size_t n = 0, i;
  OK(eoir_truth_count(e, sensor, &n));
  for (i = 0; i < n; ++i) {
    memset(out, 0, sizeof *out);
    out->struct_size = sizeof *out;
    OK(eoir_truth_get(e, sensor, i, out));
    if (strcmp(out->object, object) == 0) return 1;
  }
  return 0;
}

/* A satellite placed at a computed azimuth and elevation lands on the
 * centre of a sensor pointed there (0.05 px), and truth gives back the
 * azimuth and elevation (1e-6 deg). */
static void pointing_by_azimuth_elevation(void) {
  static const double cases[][2] = {{0.0, 45.0}, {123.4, 35.0}, {271.0, 5.0}, {200.0, 89.5}, {90.0, -10.0}};
  size_t k;
  for (k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
    const double az = cases[k][0], el = cases[k][1];
    eoir_engine e = observatory();
    eoir_state s;
    eoir_truth t;
    double r[3];
    place_at_azel(az, el, 900e3, r);
    s = state_at(EOIR_FRAME_EARTH_FIXED, r[0], r[1], r[2]);
    OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
    OK(eoir_object_set_state(e, "Sat", NULL, &s));
    OK(eoir_sensor_point_azel(e, "Scope", az, el));
    OK(eoir_render(e, "Scope"));
    CHECK(truth_of(e, "Scope", "Sat", &t));
    NEAR_ABS(t.pixel_x, CENTRE, 0.05);
    NEAR_ABS(t.pixel_y, CENTRE, 0.05);
    CHECK(t.topocentric == 1);
    NEAR_ABS(t.azimuth_deg, az, 1e-6);
    NEAR_ABS(t.elevation_deg, el, 1e-6);
    NEAR_ABS(t.range_m, 900e3, 1e-3);
    /* The pointing is held on the local horizon: an hour later the
     * Earth-fixed satellite is still at the centre. */
    set_time(e, "2010-08-25T05:00:00Z");
    OK(eoir_render(e, "Scope"));
    CHECK(truth_of(e, "Scope", "Sat", &t));
    NEAR_ABS(t.pixel_x, CENTRE, 0.05);
    NEAR_ABS(t.pixel_y, CENTRE, 0.05);
    NEAR_ABS(t.azimuth_deg, az, 1e-6);
    NEAR_ABS(t.elevation_deg, el, 1e-6);
    eoir_engine_destroy(e);
  }
}

/* Picture orientation: body +y toward the zenith. Pointed north at 30 deg,
 * a satellite 0.2 deg higher is above the centre (smaller row), one 0.2 deg
 * east (azimuth + 0.2 / cos 30) is on the right (larger column: with the
 * zenith up, west is on the left). */
static void zenith_is_up(void) {
  eoir_engine e = observatory();
  eoir_state s;
  eoir_truth t;
  double r[3];
  const double pixel_deg = 1.0 / PIXELS;
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "High"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "East"));
  place_at_azel(0.0, 30.2, 900e3, r);
  s = state_at(EOIR_FRAME_EARTH_FIXED, r[0], r[1], r[2]);
  OK(eoir_object_set_state(e, "High", NULL, &s));
  place_at_azel(0.2 / cos(30.0 * PI / 180.0), 30.0, 900e3, r);
  s = state_at(EOIR_FRAME_EARTH_FIXED, r[0], r[1], r[2]);
  OK(eoir_object_set_state(e, "East", NULL, &s));
  OK(eoir_sensor_point_azel(e, "Scope", 0.0, 30.0));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Scope", "High", &t));
  NEAR_ABS(t.pixel_x, CENTRE, 0.05);
  NEAR_ABS(t.pixel_y, CENTRE - 0.2 / pixel_deg, 0.2);
  CHECK(truth_of(e, "Scope", "East", &t));
  NEAR_ABS(t.pixel_x, CENTRE + 0.2 / pixel_deg, 0.2);
  NEAR_ABS(t.pixel_y, CENTRE, 0.2);
  eoir_engine_destroy(e);
}

/* Tracking a satellite that crosses the sky at 7 km/s 900 km away: it stays
 * at the centre without a streak during a 0.5 s integration (0.05 px), where
 * the same frame pointed by azimuth and elevation streaks it by about
 * 7 km/s x 0.5 s / 900 km = 0.22 deg (14 px). */
static void tracking_with_rates(void) {
  eoir_engine e = observatory();
  eoir_state sat, site;
  eoir_truth t;
  double r[3], streak;
  int i;
  OK(eoir_set_number(e, "Scope", "integration_time_ms", 500.0));
  place_at_azel(150.0, 50.0, 900e3, r);
  sat = state_at(EOIR_FRAME_EARTH_FIXED, r[0], r[1], r[2]);
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_object_set_state(e, "Sat", NULL, &sat));
  /* Its J2000 state, then 7 km/s across the line of sight (J2000 z cross it). */
  memset(&site, 0, sizeof site);
  site.struct_size = sizeof site;
  site.frame = EOIR_FRAME_J2000;
  OK(eoir_object_get_state(e, "Obs", &site));
  memset(&sat, 0, sizeof sat);
  sat.struct_size = sizeof sat;
  sat.frame = EOIR_FRAME_J2000;
  OK(eoir_object_get_state(e, "Sat", &sat));
  {
    const double d[3] = {sat.position[0] - site.position[0], sat.position[1] - site.position[1],
                         sat.position[2] - site.position[2]};
    double v[3] = {-d[1], d[0], 0.0};
    const double norm = sqrt(v[0] * v[0] + v[1] * v[1]);
    for (i = 0; i < 3; ++i) sat.velocity[i] = 7000.0 * v[i] / norm;
    sat.attitude[0] = 1, sat.attitude[1] = sat.attitude[2] = sat.attitude[3] = 0;
    OK(eoir_object_set_state(e, "Sat", NULL, &sat));
  }
  OK(eoir_sensor_point_at(e, "Scope", "Sat"));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Scope", "Sat", &t));
  NEAR_ABS(t.pixel_x, CENTRE, 0.05);
  NEAR_ABS(t.pixel_y, CENTRE, 0.05);
  NEAR_ABS(t.end_pixel_x - t.start_pixel_x, 0.0, 0.05);
  NEAR_ABS(t.end_pixel_y - t.start_pixel_y, 0.0, 0.05);
  NEAR_ABS(t.azimuth_deg, 150.0, 1e-6);
  NEAR_ABS(t.elevation_deg, 50.0, 1e-6);
  {
    /* The sensor's angular velocity across the line of sight is the line of
     * sight's, r x (v_target - v_site) / r^2 (1e-6); about it the picture
     * turns to keep the zenith up. */
    eoir_state scope;
    double d[3], v[3], expected[3], w[3], along = 0, r2 = 0;
    memset(&scope, 0, sizeof scope);
    scope.struct_size = sizeof scope;
    scope.frame = EOIR_FRAME_J2000;
    OK(eoir_object_get_state(e, "Scope", &scope));
    for (i = 0; i < 3; ++i) {
      d[i] = sat.position[i] - site.position[i];
      v[i] = sat.velocity[i] - site.velocity[i];
      r2 += d[i] * d[i];
    }
    expected[0] = (d[1] * v[2] - d[2] * v[1]) / r2;
    expected[1] = (d[2] * v[0] - d[0] * v[2]) / r2;
    expected[2] = (d[0] * v[1] - d[1] * v[0]) / r2;
    for (i = 0; i < 3; ++i) along += scope.angular_velocity[i] * d[i] / sqrt(r2);
    for (i = 0; i < 3; ++i) w[i] = scope.angular_velocity[i] - along * d[i] / sqrt(r2);
    for (i = 0; i < 3; ++i) NEAR_ABS(w[i], expected[i], 1e-6 * 7000.0 / 900e3);
  }
  OK(eoir_sensor_point_azel(e, "Scope", 150.0, 50.0));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Scope", "Sat", &t));
  streak = hypot(t.end_pixel_x - t.start_pixel_x, t.end_pixel_y - t.start_pixel_y);
  CHECK(streak > 10.0 && streak < 18.0);
  eoir_engine_destroy(e);
}

/* Sensors far from the Earth get no topocentric truth (flag 0, zeros), and
 * a caller of the 1.3 struct gets nothing past it. */
static void truth_in_space_and_old_callers(void) {
  eoir_engine e = NULL;
  eoir_truth t;
  size_t n = 0;
  OK(eoir_engine_create(NULL, &e));
  host_camera(e, "2010-08-25T04:00:00Z", 32, 0.5, 0.9);
  OK(put_j2000(e, "Host", 42164e3, 0, 0));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(put_j2000(e, "Sat", 42164e3, 0, 100e3));
  OK(eoir_render(e, "Cam"));
  OK(eoir_truth_count(e, "Cam", &n));
  CHECK(n == 1);
  memset(&t, 0x5a, sizeof t);
  t.struct_size = sizeof t;
  OK(eoir_truth_get(e, "Cam", 0, &t));
  CHECK(t.topocentric == 0 && t.azimuth_deg == 0.0 && t.elevation_deg == 0.0);
  memset(&t, 0x5a, sizeof t);
  t.struct_size = (uint32_t)offsetof(eoir_truth, topocentric);
  OK(eoir_truth_get(e, "Cam", 0, &t));
  CHECK(t.topocentric == 0x5a5a5a5a); /* untouched */
  CHECK(strcmp(t.object, "Sat") == 0);
  eoir_engine_destroy(e);
}

/* A site is not a vehicle: six aircraft and ground vehicles and then sites
 * up to EOIR_MAX_SITES. */
static void limits(void) {
  eoir_engine e = NULL;
  char name[32];
  int i;
  OK(eoir_engine_create(NULL, &e));
  for (i = 0; i < EOIR_MAX_VEHICLES; ++i) {
    snprintf(name, sizeof name, "Vehicle%d", i);
    OK(eoir_object_add(e, i % 2 ? EOIR_KIND_AIRCRAFT : EOIR_KIND_GROUND_VEHICLE, name));
  }
  FAILS(eoir_object_add(e, EOIR_KIND_AIRCRAFT, "Vehicle7"), EOIR_ERR_LIMIT_EXCEEDED, "aircraft plus ground vehicles");
  for (i = 0; i < EOIR_MAX_SITES; ++i) {
    snprintf(name, sizeof name, "Site%d", i);
    OK(eoir_object_add(e, EOIR_KIND_SITE, name));
  }
  FAILS(eoir_object_add(e, EOIR_KIND_SITE, "Site16"), EOIR_ERR_LIMIT_EXCEEDED, "sites");
  OK(eoir_object_remove(e, "Site0"));
  OK(eoir_object_add(e, EOIR_KIND_SITE, "Site16"));
  {
    const char* n = NULL;
    int32_t kind = 0;
    size_t count = 0;
    OK(eoir_object_count(e, &count));
    OK(eoir_object_at(e, count - 1, &n, &kind));
    CHECK(kind == EOIR_KIND_SITE && strcmp(n, "Site16") == 0);
  }
  eoir_engine_destroy(e);
}

/* Bad input: a status and a message naming the field. */
static void bad_input(void) {
  eoir_engine e = observatory();
  eoir_state s = state_at(EOIR_FRAME_GEODETIC, 10.0, 20.0, 0.0);
  double v = 0;
  FAILS(eoir_set_number(e, "Obs", "latitude_deg", 90.5), EOIR_ERR_OUT_OF_RANGE, "latitude_deg");
  FAILS(eoir_set_number(e, "Obs", "latitude_deg", -91.0), EOIR_ERR_OUT_OF_RANGE, "latitude_deg");
  FAILS(eoir_set_number(e, "Obs", "latitude_deg", NAN), EOIR_ERR_OUT_OF_RANGE, "latitude_deg");
  FAILS(eoir_set_number(e, "Obs", "longitude_deg", 400.0), EOIR_ERR_OUT_OF_RANGE, "longitude_deg");
  FAILS(eoir_set_number(e, "Obs", "longitude_deg", INFINITY), EOIR_ERR_OUT_OF_RANGE, "longitude_deg");
  FAILS(eoir_set_number(e, "Obs", "height_m", 2e5), EOIR_ERR_OUT_OF_RANGE, "height_m");
  FAILS(eoir_set_number(e, "Obs", "height_m", NAN), EOIR_ERR_OUT_OF_RANGE, "height_m");
  OK(eoir_get_number(e, "Obs", "latitude_deg", &v));
  CHECK(v == site_lat); /* refusals leave it as it was */
  FAILS(eoir_sensor_point_azel(e, "Scope", 10.0, 90.5), EOIR_ERR_OUT_OF_RANGE, "elevation_deg");
  FAILS(eoir_sensor_point_azel(e, "Scope", 10.0, -90.5), EOIR_ERR_OUT_OF_RANGE, "elevation_deg");
  FAILS(eoir_sensor_point_azel(e, "Scope", 10.0, NAN), EOIR_ERR_OUT_OF_RANGE, "elevation_deg");
  FAILS(eoir_sensor_point_azel(e, "Scope", NAN, 10.0), EOIR_ERR_OUT_OF_RANGE, "azimuth_deg");
  FAILS(eoir_sensor_point_azel(e, "Scope", 361.0, 10.0), EOIR_ERR_OUT_OF_RANGE, "azimuth_deg");
  FAILS(eoir_sensor_point_azel(e, "Obs", 10.0, 10.0), EOIR_ERR_UNKNOWN_NAME, "not a sensor");
  FAILS(eoir_sensor_point_azel(e, "Nobody", 10.0, 10.0), EOIR_ERR_UNKNOWN_NAME, "Nobody");
  FAILS(eoir_sensor_point_azel(e, NULL, 10.0, 10.0), EOIR_ERR_NULL_ARGUMENT, "sensor");
  FAILS(eoir_sensor_point_at(e, "Scope", "Obs"), EOIR_ERR_NOT_ALLOWED, "target");
  FAILS(eoir_sensor_point_at(e, "Scope", "Scope"), EOIR_ERR_NOT_ALLOWED, "target");
  FAILS(eoir_sensor_point_at(e, "Scope", "Nobody"), EOIR_ERR_UNKNOWN_NAME, "target");
  FAILS(eoir_sensor_point_at(e, "Scope", NULL), EOIR_ERR_NULL_ARGUMENT, "target");
  OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  FAILS(eoir_sensor_point_at(e, "Scope", "Stars"), EOIR_ERR_NOT_ALLOWED, "star field");
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "NoState"));
  FAILS(eoir_sensor_point_at(e, "Scope", "NoState"), EOIR_ERR_NO_STATE, "NoState");
  /* A site takes no state and has no shape. */
  FAILS(eoir_object_set_state(e, "Obs", NULL, &s), EOIR_ERR_NOT_ALLOWED, "state");
  FAILS(eoir_set_string(e, "Obs", "shape", "sphere"), EOIR_ERR_UNKNOWN_NAME, "shape");
  FAILS(eoir_snr_constraint(e, "Scope", "Obs", NULL, &v), EOIR_ERR_NOT_ALLOWED, "target");
  eoir_engine_destroy(e);
}

/* Where a site is: get_state reads back its geodetic position, its
 * attitude (east, north, up) and the Earth's rotation. */
static void site_state(void) {
  eoir_engine e = observatory();
  eoir_state s;
  double east[3], north[3], up[3], r[3];
  double w, x, y, z;
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_GEODETIC;
  OK(eoir_object_get_state(e, "Obs", &s));
  NEAR_ABS(s.position[0], site_lat, 1e-9);
  NEAR_ABS(s.position[1], site_lon, 1e-9);
  NEAR_ABS(s.position[2], site_height, 1e-6);
  s.frame = EOIR_FRAME_EARTH_FIXED;
  OK(eoir_object_get_state(e, "Obs", &s));
  geodetic_to_ecef(site_lat, site_lon, site_height, r);
  NEAR_ABS(s.position[0], r[0], 1e-6);
  NEAR_ABS(s.position[1], r[1], 1e-6);
  NEAR_ABS(s.position[2], r[2], 1e-6);
  NEAR_ABS(s.velocity[0] * s.velocity[0] + s.velocity[1] * s.velocity[1] + s.velocity[2] * s.velocity[2], 0.0, 1e-12);
  NEAR_ABS(s.angular_velocity[2], 0.0, 1e-15);
  /* Body z (the attitude's third column) is the geodetic up; body y north. */
  w = s.attitude[0], x = s.attitude[1], y = s.attitude[2], z = s.attitude[3];
  enu_basis(site_lat, site_lon, east, north, up);
  NEAR_ABS(2 * (x * z + w * y), up[0], 1e-12);
  NEAR_ABS(2 * (y * z - w * x), up[1], 1e-12);
  NEAR_ABS(1 - 2 * (x * x + y * y), up[2], 1e-12);
  NEAR_ABS(2 * (x * y - w * z), north[0], 1e-12);
  NEAR_ABS(1 - 2 * (x * x + z * z), north[1], 1e-12);
  NEAR_ABS(2 * (y * z + w * x), north[2], 1e-12);
  s.frame = EOIR_FRAME_J2000;
  OK(eoir_object_get_state(e, "Obs", &s));
  NEAR_REL(sqrt(s.angular_velocity[0] * s.angular_velocity[0] + s.angular_velocity[1] * s.angular_velocity[1] +
                s.angular_velocity[2] * s.angular_velocity[2]),
           7.292115e-5, 1e-6);
  eoir_engine_destroy(e);
}

/* Save and restore: the site, its properties and its sensor's pointing come
 * back exactly, and the restored engine renders the same truth. */
static void save_restore(void) {
  char dir[] = "/tmp/eoir_site_XXXXXX";
  char path[256];
  eoir_engine e = observatory(), r = NULL;
  eoir_state s;
  eoir_truth before, after;
  double p[3];
  const char* name = NULL;
  int32_t kind = 0;
  size_t i, count = 0;
  int found = 0;
  CHECK(mkdtemp(dir) != NULL);
  snprintf(path, sizeof path, "%s/site.scd", dir);
  place_at_azel(33.0, 20.0, 1500e3, p);
  s = state_at(EOIR_FRAME_EARTH_FIXED, p[0], p[1], p[2]);
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_object_set_state(e, "Sat", NULL, &s));
  OK(eoir_sensor_point_azel(e, "Scope", 33.0, 20.0));
  OK(eoir_render(e, "Scope"));
  CHECK(truth_of(e, "Scope", "Sat", &before));
  OK(eoir_state_save(e, path));
  OK(eoir_engine_create(NULL, &r));
  OK(eoir_state_load(r, path));
  OK(eoir_object_count(r, &count));
  for (i = 0; i < count; ++i) {
    OK(eoir_object_at(r, i, &name, &kind));
    if (strcmp(name, "Obs") == 0) found = kind == EOIR_KIND_SITE;
  }
  CHECK(found);
  {
    static const char* const props[] = {"latitude_deg", "longitude_deg", "height_m"};
    for (i = 0; i < 3; ++i) {
      double a = 0, b = 1;
      OK(eoir_get_number(e, "Obs", props[i], &a));
      OK(eoir_get_number(r, "Obs", props[i], &b));
      CHECK(a == b);
    }
  }
  OK(eoir_render(r, "Scope"));
  CHECK(truth_of(r, "Scope", "Sat", &after));
  CHECK(after.pixel_x == before.pixel_x && after.pixel_y == before.pixel_y);
  CHECK(after.azimuth_deg == before.azimuth_deg && after.elevation_deg == before.elevation_deg);
  CHECK(after.topocentric == 1);
  NEAR_ABS(after.azimuth_deg, 33.0, 1e-6);
  /* Saved again, the file is the same. */
  {
    char path2[256];
    FILE *f1, *f2;
    int same = 1, c1, c2;
    snprintf(path2, sizeof path2, "%s/site2.scd", dir);
    OK(eoir_state_save(r, path2));
    f1 = fopen(path, "rb");
    f2 = fopen(path2, "rb");
    CHECK(f1 && f2);
    if (f1 && f2)
      do {
        c1 = fgetc(f1);
        c2 = fgetc(f2);
        if (c1 != c2) same = 0;
      } while (same && c1 != EOF);
    if (f1) fclose(f1);
    if (f2) fclose(f2);
    CHECK(same);
    remove(path2);
  }
  remove(path);
  rmdir(dir);
  eoir_engine_destroy(r);
  eoir_engine_destroy(e);
}

int main(void) {
  pointing_by_azimuth_elevation();
  zenith_is_up();
  tracking_with_rates();
  truth_in_space_and_old_callers();
  limits();
  bad_input();
  site_state();
  save_restore();
  return CHECK_SUMMARY();
}
