/* Round trips as a property (issue 25, "Deliver"), C99. Each round builds a
 * state from every kind of object (central bodies, the star field,
 * satellites, aircraft, a ground vehicle, a missile, a site, sensors), every
 * shape, composites (custom and nested, and the predefined satellites),
 * every material source (built in, gray_body, a user's file, a user's file
 * redefining a built-in), a mesh file with its materials mapped, a user spectrum, every thermal and point-source
 * model, the star field's options (the bundled catalogue or a user CSV,
 * epoch, magnitude, background light) and the Earth's atmosphere: every
 * property eoir_property_info lists is moved off its default, and closed
 * sets take each of their choices across the objects and rounds. The state
 * saves, loads into a new engine and saves again: the two files are equal
 * byte for byte, and every sensor renders the same images, truth and
 * fidelity in both engines, bit for bit. Refused values (e.g. a value that
 * fits no dependent property) are skipped but must carry a message. */
#define _XOPEN_SOURCE 700
#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

#include "check.h"

#define ROUNDS 2
#define SATELLITES 10
#define SENSORS 6

static char dir[4096];
static int refusals = 0;

static const char* at(const char* name) {
  static char buf[8][4200];
  static int k = 0;
  k = (k + 1) % 8;
  snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
  return buf[k];
}

/* A call that may refuse a value: a status with a message, never INTERNAL. */
static void tolerated(eoir_status st, const char* object, const char* property) {
  ++check_count;
  if (st == EOIR_OK) return;
  ++refusals;
  if (getenv("EOIR_TEST_VERBOSE")) printf("refused %s.%s: %s\n", object, property, eoir_last_error());
  if (st == EOIR_ERR_INTERNAL || eoir_last_error()[0] == '\0') {
    ++check_failures;
    fprintf(stderr, "%s.%s -> %s (\"%s\")\n", object, property, eoir_status_name(st), eoir_last_error());
  }
}

static int in_range(double x, const eoir_property_info* p) {
  const int lo = (p->range_open & 1u) ? x > p->minimum : x >= p->minimum;
  const int hi = (p->range_open & 2u) ? x < p->maximum : x <= p->maximum;
  return isfinite(x) && lo && hi;
}

/* The k-th of a comma-separated list of choices, into out. */
static const char* nth_choice(const char* choices, int k, char* out, size_t capacity) {
  int n = 1, i;
  const char* p = choices;
  const char* end;
  size_t len;
  for (p = choices; *p; ++p) n += *p == ',';
  k %= n;
  p = choices;
  for (i = 0; i < k; ++i) p = strchr(p, ',') + 1;
  end = strchr(p, ',');
  len = end ? (size_t)(end - p) : strlen(p);
  if (len >= capacity) len = capacity - 1;
  memcpy(out, p, len);
  out[len] = '\0';
  return out;
}

/* Values that keep a frame small and cheap, or that a property's own
 * default cannot be scaled from (0 meaning automatic); rounds vary them. */
static int explicit_number(const char* object_kind, const char* name, int round, double* value) {
  static const struct {
    const char* name;
    double base, step;
  } table[] = {{"horizontal_pixels", 16, 1},
               {"vertical_pixels", 12, 1},
               {"defocus_mm", 0.02, 0.02},
               {"jitter_mrad", 0.002, 0.002},
               {"error_budget", 0.0, 0.02},
               {"psf_grid_size", 128, 0},
               {"latitude_deg", 33.7, 1},
               {"longitude_deg", -118.3, 1},
               {"height_m", 30, 100},
               {"catalog_epoch_year", 2000.0, 2.5},
               {"display_gain_step", 1, 1},
               {"limiting_magnitude", 8.0, 0.5}};
  size_t i;
  if (strcmp(name, "patch_size_m") == 0) {
    *value = strcmp(object_kind, "central_body") == 0 ? 4e5 + 1e5 * round : 0.3 + 0.1 * round;
    return 1;
  }
  for (i = 0; i < sizeof table / sizeof table[0]; ++i)
    if (strcmp(table[i].name, name) == 0) {
      *value = table[i].base + table[i].step * round;
      if (strcmp(name, "psf_grid_size") == 0) *value = round % 2 ? 256 : 128;
      return 1;
    }
  return 0;
}

/* A value off the default: the default scaled by a few per cent (or moved
 * by one), else a point of the range. */
static double moved(double v, const eoir_property_info* p, int integer, int round) {
  const double f = 0.05 * (1 + round);
  double w = integer ? v + 1 + round : v * (1 + f);
  if (v == 0 && !integer) w = 0.01 * (1 + round);
  if (in_range(w, p)) return w;
  w = integer ? v - 1 - round : v * (1 - f);
  if (in_range(w, p) && w != v) return w;
  if (isfinite(p->minimum) && isfinite(p->maximum)) return p->minimum + (p->maximum - p->minimum) * 0.37;
  return v;
}

/* Moves every property of `object` off its default (names handled by the
 * caller are skipped); k is the object's index among its kind. */
static void move_properties(eoir_engine e, const char* object, const char* kind, int k, int round) {
  eoir_property_info p;
  size_t i;
  char text[256];
  for (i = 0;; ++i) {
    memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    if (eoir_property_info_at(e, object, i, &p) != EOIR_OK) break;
    if (strcmp(p.name, "material") == 0 || strcmp(p.name, "composite") == 0 || strcmp(p.name, "spectrum") == 0 ||
        strcmp(p.name, "catalog_file") == 0)
      continue;
    /* every body names the mesh (shape mesh, a choice of shape, renders it) */
    if (strcmp(p.name, "mesh_file") == 0) {
      tolerated(eoir_set_string(e, object, p.name, at("rt_cube.obj")), object, p.name);
      continue;
    }
    if (strcmp(p.name, "mesh_materials") == 0) {
      tolerated(eoir_set_string(e, object, p.name, "{\"hull\": {\"material\": \"gold\", \"temperature_K\": 310}}"),
                object, p.name);
      continue;
    }
    /* setting W_rms makes image_quality custom: every other sensor keeps its preset */
    if (strcmp(p.name, "wavefront_error_rms_waves") == 0 && (k + round) % 2 == 0) continue;
    if (p.type == EOIR_TYPE_STRING && p.choices[0] != '\0') {
      tolerated(eoir_set_string(e, object, p.name, nth_choice(p.choices, k + round, text, sizeof text)), object,
                p.name);
    } else if (p.type == EOIR_TYPE_NUMBER || p.type == EOIR_TYPE_INTEGER) {
      double v = 0;
      if (!explicit_number(kind, p.name, round, &v)) {
        if (p.type == EOIR_TYPE_NUMBER) {
          if (eoir_get_number(e, object, p.name, &v) != EOIR_OK) continue;
        } else {
          int64_t n = 0;
          if (eoir_get_integer(e, object, p.name, &n) != EOIR_OK) continue;
          v = (double)n;
        }
        v = moved(v, &p, p.type == EOIR_TYPE_INTEGER, round);
      }
      tolerated(p.type == EOIR_TYPE_NUMBER ? eoir_set_number(e, object, p.name, v)
                                           : eoir_set_integer(e, object, p.name, (int64_t)v),
                object, p.name);
    } else if (p.type == EOIR_TYPE_BOOL) {
      int32_t b = 0;
      if (eoir_get_bool(e, object, p.name, &b) != EOIR_OK) continue;
      tolerated(eoir_set_bool(e, object, p.name, (k + round) % 2 ? b : !b), object, p.name);
    } else if (p.type == EOIR_TYPE_ARRAY) {
      double values[64];
      size_t n = 0, j;
      if (eoir_get_array(e, object, p.name, values, 64, &n) != EOIR_OK) continue;
      for (j = 0; j < n; ++j) values[j] *= 1.0 + 0.1 * (1 + round);
      tolerated(eoir_set_array(e, object, p.name, values, n), object, p.name);
    }
  }
}

static const char* const composites[] = {
    "leo_earth_observing", "leo_communications", "geo_communications",
    "[{\"shape\": \"box\", \"dimensions_m\": [1, 1.5, 2], \"material\": \"rt_user\"},"
    " {\"shape\": \"plate\", \"dimensions_m\": [3, 1], \"offset_m\": [0, 2, 0], \"orientation_wxyz\": [0.7071067811865476, "
    "0.7071067811865476, 0, 0], \"temperature_K\": 250, \"reflectance\": 0.2},"
    " {\"parts\": [{\"shape\": \"cylinder\", \"dimensions_m\": [0.2, 1], \"material\": \"gold\"},"
    " {\"shape\": \"sphere\", \"dimensions_m\": [0.3], \"offset_m\": [0, 0, 1]}], \"offset_m\": [0, -1, 0]}]"};
static const char* const materials[] = {"gray_body", "aluminum", "gold_mli", "rt_user", "gold"};
static const char* const spectra[] = {"", "rt_glow", "sun"};
static const char* const thermal_models[] = {"uniform", "subsolar", "eclipse"};

static void write_files(void) {
  FILE* f;
  write_text(at("rt_user.json"),
             "{\"format\": \"eoir-material\", \"version\": 1, \"name\": \"rt_user\", \"description\": \"round trips\",\n"
             " \"sources\": [\"round_trip_test.c\"], \"brdf\": {\"k0\": 0.3, \"k1\": 0.2, \"alpha\": 40, \"beta\": 5},\n"
             " \"wavelength_um\": [0.28, 0.5, 1.0, 3.0, 10.0, 28.0], \"reflectance\": [0.1, 0.6, 0.7, 0.4, 0.05, 0.02]}\n");
  /* a user's "gold": redefines the built-in one */
  write_text(at("gold.json"),
             "{\"format\": \"eoir-material\", \"version\": 1, \"name\": \"gold\", \"description\": \"redefined\",\n"
             " \"sources\": [\"round_trip_test.c\"], \"brdf\": {\"k0\": 0.9, \"k1\": 0.1, \"alpha\": 2, \"beta\": 2},\n"
             " \"wavelength_um\": [0.28, 28.0], \"reflectance\": [0.33, 0.33]}\n");
  write_text(at("rt_cube.obj"),
             "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv -0.5 0.5 -0.5\nv 0.5 0.5 -0.5\n"
             "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv -0.5 0.5 0.5\nv 0.5 0.5 0.5\nusemtl hull\n"
             "f 1 3 2\nf 2 3 4\nf 5 6 7\nf 6 8 7\nf 1 2 5\nf 2 6 5\nf 3 7 4\nf 4 7 8\nf 1 5 3\nf 3 5 7\nf 2 4 6\nf 4 8 6\n");
  f = fopen(at("stars.csv"), "wb");
  CHECK(f != NULL);
  if (f) {
    int i;
    fputs("id,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,parallax_mas,v_mag,b_v\n", f);
    for (i = 0; i < 200; ++i)
      fprintf(f, "rt%d,%.6f,%.6f,%.2f,%.2f,%.2f,%.2f,%.2f\n", i, fmod(i * 37.1, 360.0), -80.0 + fmod(i * 11.3, 160.0),
              (i % 7) * 10.0, (i % 5) * -8.0, (i % 3) * 2.0, 2.0 + fmod(i * 0.37, 7.0), -0.2 + fmod(i * 0.1, 1.8));
    fclose(f);
  }
}

/* Builds round r's state in e. */
static void build(eoir_engine e, int r) {
  static const char* const bodies[] = {"Earth", "Moon", "Mars", "Jupiter"};
  static const struct {
    int32_t kind;
    const char* name;
    const char* kind_name;
    double lat, lon, h;
  } vehicles[] = {{EOIR_KIND_AIRCRAFT, "A0", "aircraft", 34.0, -118.0, 10000},
                  {EOIR_KIND_AIRCRAFT, "A1", "aircraft", 34.1, -118.1, 9000},
                  {EOIR_KIND_GROUND_VEHICLE, "G0", "ground_vehicle", 33.9, -118.2, 50},
                  {EOIR_KIND_MISSILE, "M0", "missile", 34.2, -118.4, 30000}};
  const double wl[3] = {0.28, 5.0, 28.0}, L[3] = {1e-4, 3e-4, 1e-5};
  char name[32], iso[64];
  eoir_time t;
  size_t i;
  int j;

  snprintf(iso, sizeof iso, "2010-03-2%dT%02d:00:00Z", r % 9, 6 + 3 * r);
  OK(eoir_time_from_iso(iso, &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_material_load(e, at("rt_user.json")));
  OK(eoir_material_load(e, at("gold.json")));
  OK(eoir_spectrum_add(e, "rt_glow", wl, L, 3));

  for (i = 0; i < sizeof bodies / sizeof bodies[0]; ++i) {
    OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, bodies[i]));
    move_properties(e, bodies[i], "central_body", (int)i, r);
    tolerated(eoir_set_string(e, bodies[i], "material", materials[(i + (size_t)r) % 5]), bodies[i], "material");
    /* climatology is the Earth's: the others take the other models */
    if (i > 0) OK(eoir_set_string(e, bodies[i], "thermal_model", thermal_models[(i + (size_t)r) % 3]));
  }
  OK(eoir_set_string(e, "Earth", "atmosphere", r % 2 ? "simple" : "none"));
  if (r % 2 == 0) OK(eoir_set_string(e, "Earth", "thermal_model", "climatology"));

  OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  move_properties(e, "Stars", "star_field", 0, r);
  if (r % 2 == 0) OK(eoir_set_string(e, "Stars", "catalog_file", at("stars.csv")));

  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Host"));
  OK(eoir_set_string(e, "Host", "shape", "none"));
  OK(put_j2000(e, "Host", 4.2e7, 0, 0));
  for (j = 0; j < SATELLITES; ++j) {
    eoir_state s = state_at(EOIR_FRAME_J2000, 4.2e7 + 30.0 * j, 80.0 * (j - 4.5), 1.0e4 + 500.0 * j);
    s.velocity[1] = 3.0 * j;
    s.angular_velocity[2] = 0.01 * j;
    snprintf(name, sizeof name, "S%d", j);
    OK(eoir_object_add(e, EOIR_KIND_SATELLITE, name));
    tolerated(eoir_set_string(e, name, "composite", composites[(j + r) % 4]), name, "composite");
    move_properties(e, name, "satellite", j, r);
    tolerated(eoir_set_string(e, name, "material", materials[(j + r) % 5]), name, "material");
    tolerated(eoir_set_string(e, name, "spectrum", spectra[(j + r) % 3]), name, "spectrum");
    OK(eoir_object_set_state(e, name, NULL, &s));
  }
  for (i = 0; i < sizeof vehicles / sizeof vehicles[0]; ++i) {
    const eoir_state s = state_at(EOIR_FRAME_GEODETIC, vehicles[i].lat, vehicles[i].lon, vehicles[i].h);
    OK(eoir_object_add(e, vehicles[i].kind, vehicles[i].name));
    move_properties(e, vehicles[i].name, vehicles[i].kind_name, (int)i, r);
    tolerated(eoir_set_string(e, vehicles[i].name, "material", materials[(i + (size_t)r + 2) % 5]), vehicles[i].name,
              "material");
    OK(eoir_object_set_state(e, vehicles[i].name, NULL, &s));
  }
  OK(eoir_object_add(e, EOIR_KIND_SITE, "T0"));
  move_properties(e, "T0", "site", 0, r);

  /* Sensors: four on Host tracking satellites, one on the site looking up,
   * one on an aircraft tracking the missile. */
  for (j = 0; j < SENSORS; ++j) {
    const char* parent = j < 4 ? "Host" : j == 4 ? "T0" : "A0";
    snprintf(name, sizeof name, "C%d", j);
    OK(eoir_sensor_add(e, name, parent));
    move_properties(e, name, "sensor", j, r);
  }
  for (j = 0; j < 4; ++j) {
    char target[8];
    snprintf(name, sizeof name, "C%d", j);
    snprintf(target, sizeof target, "S%d", (j + r) % SATELLITES);
    OK(eoir_sensor_point_at(e, name, target));
  }
  OK(eoir_sensor_point_azel(e, "C4", 20.0 * r, 60.0));
  OK(eoir_sensor_point_at(e, "C5", "M0"));
}

static long file_size(const char* path) {
  FILE* f = fopen(path, "rb");
  long n = -1;
  if (f && fseek(f, 0, SEEK_END) == 0) n = ftell(f);
  if (f) fclose(f);
  return n;
}

/* 1 if the two files hold the same bytes. */
static int same_file(const char* a, const char* b) {
  FILE* fa = fopen(a, "rb");
  FILE* fb = fopen(b, "rb");
  int ca = 0, cb = 0;
  long offset = 0;
  if (fa && fb) {
    do {
      ca = fgetc(fa);
      cb = fgetc(fb);
      ++offset;
    } while (ca == cb && ca != EOF);
    if (ca != cb) fprintf(stderr, "%s and %s differ at byte %ld\n", a, b, offset - 1);
  }
  if (fa) fclose(fa);
  if (fb) fclose(fb);
  return fa && fb && ca == cb;
}

/* Every image, the truth and the fidelity of `sensor` agree in e and f;
 * returns the sum of e's noise-free sensor image. */
static double same_frame(eoir_engine e, eoir_engine f, const char* sensor, int round) {
  static const int32_t kinds[] = {EOIR_IMAGE_SCENE_RADIANCE, EOIR_IMAGE_SCENE_DISPLAY, EOIR_IMAGE_SENSOR_ELECTRONS,
                                  EOIR_IMAGE_SENSOR_MEAN, EOIR_IMAGE_SENSOR_DISPLAY};
  size_t k, te = 0, tf = 0, le = 0, lf = 0;
  double sum = 0;
  for (k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) {
    eoir_image_info ie, jf;
    size_t n, bytes, j;
    void *a, *b;
    memset(&ie, 0, sizeof ie);
    memset(&jf, 0, sizeof jf);
    ie.struct_size = jf.struct_size = sizeof ie;
    OK(eoir_image_info_get(e, sensor, kinds[k], &ie));
    OK(eoir_image_info_get(f, sensor, kinds[k], &jf));
    CHECK(ie.width == jf.width && ie.height == jf.height && ie.width > 0);
    CHECK(memcmp(ie.time_jd_utc, jf.time_jd_utc, sizeof ie.time_jd_utc) == 0);
    CHECK(ie.boresight_ra_deg == jf.boresight_ra_deg && ie.boresight_dec_deg == jf.boresight_dec_deg &&
          ie.up_ra_deg == jf.up_ra_deg && ie.up_dec_deg == jf.up_dec_deg);
    if (ie.width != jf.width || ie.height != jf.height) continue;
    n = (size_t)ie.width * ie.height;
    if (kinds[k] == EOIR_IMAGE_SCENE_DISPLAY || kinds[k] == EOIR_IMAGE_SENSOR_DISPLAY) {
      bytes = n;
      a = malloc(bytes);
      b = malloc(bytes);
      OK(eoir_image_get_bytes(e, sensor, kinds[k], (uint8_t*)a, n));
      OK(eoir_image_get_bytes(f, sensor, kinds[k], (uint8_t*)b, n));
    } else {
      bytes = n * sizeof(double);
      a = malloc(bytes);
      b = malloc(bytes);
      OK(eoir_image_get(e, sensor, kinds[k], (double*)a, n));
      OK(eoir_image_get(f, sensor, kinds[k], (double*)b, n));
      if (kinds[k] == EOIR_IMAGE_SENSOR_MEAN)
        for (j = 0; j < n; ++j) sum += ((double*)a)[j];
    }
    ++check_count;
    if (memcmp(a, b, bytes) != 0) {
      ++check_failures;
      fprintf(stderr, "round %d: %s image kind %d differs after the round trip\n", round, sensor, (int)kinds[k]);
    }
    free(a);
    free(b);
  }
  OK(eoir_truth_count(e, sensor, &te));
  OK(eoir_truth_count(f, sensor, &tf));
  CHECK(te == tf);
  for (k = 0; k < te && k < tf; ++k) {
    eoir_truth x, y;
    memset(&x, 0, sizeof x);
    memset(&y, 0, sizeof y);
    x.struct_size = y.struct_size = sizeof x;
    OK(eoir_truth_get(e, sensor, k, &x));
    OK(eoir_truth_get(f, sensor, k, &y));
    CHECK(strcmp(x.object, y.object) == 0 && x.pixel_x == y.pixel_x && x.pixel_y == y.pixel_y && x.snr == y.snr &&
          x.effective_radiance == y.effective_radiance);
  }
  OK(eoir_frame_fidelity_get(e, sensor, NULL, 0, &le));
  OK(eoir_frame_fidelity_get(f, sensor, NULL, 0, &lf));
  CHECK(le == lf);
  if (le == lf && le > 0) {
    char* a = (char*)malloc(le + 1);
    char* b = (char*)malloc(lf + 1);
    OK(eoir_frame_fidelity_get(e, sensor, a, le + 1, &le));
    OK(eoir_frame_fidelity_get(f, sensor, b, lf + 1, &lf));
    CHECK(strcmp(a, b) == 0);
    free(a);
    free(b);
  }
  return sum;
}

int main(void) {
  int r, j;
  snprintf(dir, sizeof dir, "%s/eoir_round_trip_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (mkdtemp(dir) == NULL) return perror("mkdtemp"), 2;
  write_files();

  for (r = 0; r < ROUNDS; ++r) {
    eoir_engine e = NULL, f = NULL;
    char first[32], second[32];
    double signal = 0;
    snprintf(first, sizeof first, "round%d.scd", r);
    snprintf(second, sizeof second, "round%d_again.scd", r);
    OK(eoir_engine_create(NULL, &e));
    build(e, r);
    OK(eoir_state_save(e, at(first)));
    OK(eoir_engine_create(NULL, &f));
    OK(eoir_state_load(f, at(first)));
    OK(eoir_state_save(f, at(second)));
    CHECK(file_size(at(first)) > 0);
    ++check_count;
    if (!same_file(at(first), at(second))) {
      ++check_failures;
      fprintf(stderr, "round %d: the state saved again differs (%s)\n", r, dir);
    }
    for (j = 0; j < SENSORS; ++j) {
      char sensor[8];
      snprintf(sensor, sizeof sensor, "C%d", j);
      OK(eoir_render(e, sensor));
      OK(eoir_render(f, sensor));
      signal += same_frame(e, f, sensor, r);
    }
    CHECK(signal > 0); /* the frames show something */
    eoir_engine_destroy(e);
    eoir_engine_destroy(f);
  }
  printf("%d values refused with a message\n", refusals);
  if (check_failures == 0 && !getenv("EOIR_TEST_KEEP")) {
    char cmd[4200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
  }
  return CHECK_SUMMARY();
}
