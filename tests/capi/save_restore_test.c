/* C ABI: save and restore (spec 3.4). A restore reproduces every data
 * provider exactly; refused files leave the engine as it was; writes are
 * atomic. */
#include <stdlib.h>
#include <unistd.h>

#include "table3_sensor.h"

/* Writes every scalar and curve element of every static group of `sensor`
 * into out (in enumeration order); returns the count. */
static size_t snapshot(eoir_engine e, const char* sensor, double* out, size_t cap) {
  size_t gi, ei, n = 0;
  const char* g;
  for (gi = 0; eoir_provider_group_at(gi, &g) == EOIR_OK; ++gi) {
    eoir_element_info info;
    memset(&info, 0, sizeof info);
    info.struct_size = sizeof info;
    if (strstr(g, "Target")) continue;
    for (ei = 0; eoir_provider_element_at(g, ei, &info) == EOIR_OK; ++ei) {
      if (info.type == EOIR_TYPE_CURVE) {
        double x[4096], y[4096];
        size_t k, count = 0;
        OK(eoir_provider_get_curve(e, g, info.name, sensor, NULL, x, y, 4096, &count));
        for (k = 0; k < count && n + 2 <= cap; ++k) {
          out[n++] = x[k];
          out[n++] = y[k];
        }
      } else if (n < cap) {
        OK(eoir_provider_get(e, g, info.name, sensor, NULL, &out[n++]));
      }
    }
  }
  return n;
}

static char* read_text(const char* path) {
  FILE* f = fopen(path, "rb");
  long size;
  char* text;
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  size = ftell(f);
  fseek(f, 0, SEEK_SET);
  text = (char*)calloc((size_t)size + 1, 1);
  if (fread(text, 1, (size_t)size, f) != (size_t)size) text[0] = 0;
  fclose(f);
  return text;
}

int main(void) {
  static double before[20000], after[20000];
  char dir[] = "/tmp/eoir_scd_XXXXXX";
  char path[256], bad[256], sensor_path[256];
  eoir_engine e = NULL;
  eoir_time t;
  eoir_state s;
  size_t n1, n2, count;
  char* text;
  char* text2;
  CHECK(mkdtemp(dir) != NULL);
  snprintf(path, sizeof path, "%s/scenario.scd", dir);
  snprintf(bad, sizeof bad, "%s/bad.scd", dir);
  snprintf(sensor_path, sizeof sensor_path, "%s/sensor.json", dir);

  OK(eoir_engine_create(NULL, &e));
  OK(eoir_time_from_iso("2010-08-25T18:00:00.125Z", &t));
  OK(eoir_engine_set_time(e, &t));
  OK(eoir_object_add(e, EOIR_KIND_CENTRAL_BODY, "Earth"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Satellite1"));
  memset(&s, 0, sizeof s);
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_J2000;
  s.position[0] = 42164.2e3;
  s.velocity[1] = 3074.66;
  s.attitude[0] = 0.7071067811865476;
  s.attitude[3] = 0.7071067811865476;
  OK(eoir_object_set_state(e, "Satellite1", NULL, &s));
  OK(eoir_set_string(e, "Satellite1", "shape", "cylinder"));
  add_table3_sensor(e, "Satellite1", "Sensor1");
  OK(eoir_set_string(e, "Sensor1", "image_quality", "moderate"));
  OK(eoir_set_number(e, "Sensor1", "jitter_mrad", 0.013));
  n1 = snapshot(e, "Sensor1", before, 20000);
  CHECK(n1 > 40);
  OK(eoir_state_save(e, path));

  /* change everything, then restore */
  OK(eoir_set_number(e, "Sensor1", "f_number", 7.0));
  OK(eoir_object_remove(e, "Satellite1"));
  OK(eoir_state_load(e, path));
  n2 = snapshot(e, "Sensor1", after, 20000);
  CHECK(n1 == n2);
  CHECK(memcmp(before, after, n1 * sizeof(double)) == 0); /* exactly */
  {
    eoir_state got;
    eoir_time now;
    memset(&got, 0, sizeof got);
    got.struct_size = sizeof got;
    OK(eoir_object_get_state(e, "Satellite1", &got));
    CHECK(got.position[0] == 42164.2e3 && got.attitude[3] == 0.7071067811865476);
    OK(eoir_engine_get_time(e, EOIR_TIME_UTC, &now));
    CHECK(fabs(((now.jd1 - t.jd1) + (now.jd2 - t.jd2)) * 86400.0) < 1e-6);
  }
  /* saving the restored engine gives the same file */
  OK(eoir_state_save(e, bad));
  text = read_text(path);
  text2 = read_text(bad);
  CHECK(text && text2 && strcmp(text, text2) == 0);
  free(text2);

  /* refused files leave the engine as it was */
  {
    char* truncated = (char*)malloc(strlen(text) / 2 + 1);
    memcpy(truncated, text, strlen(text) / 2);
    truncated[strlen(text) / 2] = 0;
    write_text(bad, truncated);
    free(truncated);
  }
  OK(eoir_set_number(e, "Sensor1", "f_number", 7.0));
  FAILS(eoir_state_load(e, bad), EOIR_ERR_CORRUPT_FILE, "not valid JSON");
  /* (format version 2 added the user's materials and spectra: 3 is the newer one) */
  write_text(bad, "{\"format\":\"eoir-scd\",\"version\":3,\"engine\":{},\"time\":{},\"objects\":[]}");
  FAILS(eoir_state_load(e, bad), EOIR_ERR_FILE_VERSION, "version");
  write_text(bad, "{\"format\":\"eoir-scd\",\"version\":1,\"engine\":{},\"time\":{},\"objects\":[],\"colour\":1}");
  FAILS(eoir_state_load(e, bad), EOIR_ERR_CORRUPT_FILE, "scd.colour");
  {
    /* an unknown property deep inside */
    char* p = strstr(text, "\"f_number\"");
    CHECK(p != NULL);
    if (p) {
      memcpy(p, "\"g_number\"", 10);
      write_text(bad, text);
      FAILS(eoir_state_load(e, bad), EOIR_ERR_CORRUPT_FILE, "g_number");
      memcpy(p, "\"f_number\"", 10);
    }
  }
  FAILS(eoir_state_load(e, "/nonexistent/dir/x.scd"), EOIR_ERR_IO, "/nonexistent/dir/x.scd");
  {
    double f = 0;
    OK(eoir_get_number(e, "Sensor1", "f_number", &f));
    CHECK(f == 7.0); /* unchanged by the refused loads */
  }
  /* a failed save leaves the old file and no temporary */
  FAILS(eoir_state_save(e, "/nonexistent/dir/x.scd"), EOIR_ERR_IO, "/nonexistent/dir");
  OK(eoir_object_count(e, &count));

  /* a sensor definition on its own */
  OK(eoir_sensor_save(e, "Sensor1", sensor_path));
  OK(eoir_sensor_add(e, "Sensor2", "Earth"));
  OK(eoir_sensor_load(e, "Sensor2", sensor_path));
  {
    double a = 0, b = 0;
    OK(eoir_provider_get(e, "EOIR Sensor Optics", "Ensquared Energy", "Sensor1", NULL, &a));
    OK(eoir_provider_get(e, "EOIR Sensor Optics", "Ensquared Energy", "Sensor2", NULL, &b));
    CHECK(a == b);
  }
  write_text(bad, "{\"format\":\"eoir-sensor\",\"version\":1,\"parameters\":{\"band_low_um\":9,\"band_high_um\":8}}");
  FAILS(eoir_sensor_load(e, "Sensor2", bad), EOIR_ERR_CORRUPT_FILE, "band_high_um");
  FAILS(eoir_sensor_load(e, "Satellite1", sensor_path), EOIR_ERR_UNKNOWN_NAME, "not a sensor");

  free(text);
  eoir_engine_destroy(e);
  {
    char cmd[300];
    snprintf(cmd, sizeof cmd, "ls -A %s | grep -c tmp > /dev/null && exit 1; rm -rf %s", dir, dir);
    CHECK(system(cmd) == 0); /* no temporary files left behind */
  }
  return CHECK_SUMMARY();
}
