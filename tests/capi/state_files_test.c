/* State and sensor files under hostile conditions (issue 11 item 8c), C99:
 *  - 1e999, a duplicate key or 100,000-deep nesting is EOIR_ERR_CORRUPT_FILE
 *    naming the field and the file (not EOIR_ERR_INTERNAL, not a crash);
 *  - /dev/zero (not a regular file) and a file over the 64 MiB cap are
 *    refused at once;
 *  - a temporary file left by a killed save is removed by the next save,
 *    one that a live writer holds (flock) is not;
 *  - a save keeps the file's mode (0600 stays 0600), writes through a
 *    symbolic link to its target and leaves the link a link. */
#define _XOPEN_SOURCE 700
#define _DEFAULT_SOURCE
#include <fcntl.h>
#include <stdlib.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"

static char dir[4096];

static const char* at(const char* name) {
  static char buf[8][4200];
  static int k = 0;
  k = (k + 1) % 8;
  snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
  return buf[k];
}

static char* read_text(const char* path) {
  FILE* f = fopen(path, "rb");
  long n;
  char* s;
  if (f == NULL) return NULL;
  fseek(f, 0, SEEK_END);
  n = ftell(f);
  fseek(f, 0, SEEK_SET);
  s = (char*)malloc((size_t)n + 1);
  if (s == NULL || fread(s, 1, (size_t)n, f) != (size_t)n) n = 0;
  if (s) s[n] = 0;
  fclose(f);
  return s;
}

/* text with the first `from` replaced by `to` (caller frees) */
static char* replaced(const char* text, const char* from, const char* to) {
  const char* p = strstr(text, from);
  size_t n = strlen(text) - strlen(from) + strlen(to) + 1, head;
  char* out = (char*)malloc(n);
  if (p == NULL || out == NULL) {
    fprintf(stderr, "'%s' not found\n", from);
    exit(2);
  }
  head = (size_t)(p - text);
  memcpy(out, text, head);
  strcpy(out + head, to);
  strcat(out, p + strlen(from));
  return out;
}

static int exists(const char* path) {
  struct stat st;
  return lstat(path, &st) == 0;
}

int main(void) {
  eoir_engine e = NULL;
  char* scd;
  char* sensor;
  char* bad;
  struct stat st;

  snprintf(dir, sizeof dir, "%s/eoir_state_files_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (mkdtemp(dir) == NULL) return perror("mkdtemp"), 2;
  umask(022);
  alarm(120); /* a hang (reading /dev/zero forever) fails instead of blocking */

  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_sensor_add(e, "Cam", "Sat"));
  OK(eoir_state_save(e, at("good.scd")));
  OK(eoir_sensor_save(e, "Cam", at("good.json")));
  scd = read_text(at("good.scd"));
  sensor = read_text(at("good.json"));
  CHECK(scd != NULL && sensor != NULL && strstr(scd, "\"temperature_K\"") && strstr(sensor, "\"f_number\""));

  /* numbers beyond a double: corrupt file naming the field and the file */
  bad = replaced(scd, "\"temperature_K\": ", "\"temperature_K\": 1e999, \"x\": ");
  write_text(at("overflow.scd"), bad);
  free(bad);
  FAILS(eoir_state_load(e, at("overflow.scd")), EOIR_ERR_CORRUPT_FILE, "properties.temperature_K: number out of range");
  FAILS(eoir_state_load(e, at("overflow.scd")), EOIR_ERR_CORRUPT_FILE, "overflow.scd");
  bad = replaced(sensor, "\"f_number\": ", "\"f_number\": -1e999, \"x\": ");
  write_text(at("overflow.json"), bad);
  free(bad);
  FAILS(eoir_sensor_load(e, "Cam", at("overflow.json")), EOIR_ERR_CORRUPT_FILE, "parameters.f_number: number out of range");
  FAILS(eoir_sensor_load(e, "Cam", at("overflow.json")), EOIR_ERR_CORRUPT_FILE, "overflow.json");

  /* a field of the wrong type (found by fuzz.material_load in its loader) */
  bad = replaced(scd, "\"parent\": \"Sat\"", "\"parent\": 5");
  CHECK(strcmp(bad, scd) != 0);
  write_text(at("parent.scd"), bad);
  free(bad);
  FAILS(eoir_state_load(e, at("parent.scd")), EOIR_ERR_CORRUPT_FILE, "scd.objects[");
  FAILS(eoir_state_load(e, at("parent.scd")), EOIR_ERR_CORRUPT_FILE, ".parent: missing or of the wrong type");
  bad = replaced(sensor, "\"name\": \"Cam\"", "\"name\": []");
  CHECK(strcmp(bad, sensor) != 0);
  write_text(at("name.json"), bad);
  free(bad);
  FAILS(eoir_sensor_load(e, "Cam", at("name.json")), EOIR_ERR_CORRUPT_FILE, "sensor.name: missing or of the wrong type");

  /* an integer field given as a huge float (found by fuzz.sensor_load: the
   * conversion was undefined) or out of its type's range */
  bad = replaced(sensor, "\"version\": 1", "\"version\": 1.1e112");
  CHECK(strcmp(bad, sensor) != 0);
  write_text(at("version.json"), bad);
  free(bad);
  FAILS(eoir_sensor_load(e, "Cam", at("version.json")), EOIR_ERR_CORRUPT_FILE, "sensor.version: expected an integer");
  {  /* the seed's digits replaced by -1 */
    const char* seed = strstr(scd, "\"seed\": ");
    const char* end = seed ? seed + strlen("\"seed\": ") + strspn(seed + strlen("\"seed\": "), "0123456789") : NULL;
    char* digits = (char*)malloc(64);
    CHECK(end != NULL && digits != NULL && end - seed < 60);
    memcpy(digits, seed, (size_t)(end - seed));
    digits[end - seed] = '\0';
    bad = replaced(scd, digits, "\"seed\": -1");
    free(digits);
  }
  CHECK(strcmp(bad, scd) != 0);
  write_text(at("seed.scd"), bad);
  free(bad);
  FAILS(eoir_state_load(e, at("seed.scd")), EOIR_ERR_CORRUPT_FILE, "scd.engine.seed: integer out of range [0, ");

  /* a key given twice */
  bad = replaced(sensor, "\"f_number\": ", "\"f_number\": 2.0, \"f_number\": ");
  write_text(at("duplicate.json"), bad);
  free(bad);
  FAILS(eoir_sensor_load(e, "Cam", at("duplicate.json")), EOIR_ERR_CORRUPT_FILE, "parameters.f_number: duplicate key");

  /* 100,000-deep nesting */
  {
    const size_t depth = 100000;
    char* deep = (char*)malloc(2 * depth + 64);
    size_t i, n = 0;
    n += (size_t)sprintf(deep, "{\"format\": ");
    for (i = 0; i < depth; ++i) deep[n++] = '[';
    for (i = 0; i < depth; ++i) deep[n++] = ']';
    strcpy(deep + n, "}");
    write_text(at("deep.scd"), deep);
    free(deep);
    FAILS(eoir_state_load(e, at("deep.scd")), EOIR_ERR_CORRUPT_FILE, "nested deeper than 64");
  }

  /* huge inputs are refused without reading them; devices are not files
   * (issue 25, item 3: capi.special_files) */
  FAILS(eoir_state_load(e, "/dev/zero"), EOIR_ERR_IO, "'/dev/zero' is not a regular file");
  FAILS(eoir_sensor_load(e, "Cam", "/dev/zero"), EOIR_ERR_IO, "'/dev/zero' is not a regular file");
  {
    int fd = open(at("sparse.scd"), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    CHECK(fd >= 0 && ftruncate(fd, (off_t)65 << 20) == 0);
    if (fd >= 0) close(fd);
    FAILS(eoir_state_load(e, at("sparse.scd")), EOIR_ERR_CORRUPT_FILE, "sparse.scd' is larger than 64 MiB");
  }
  /* the engine is still usable and unchanged after every refusal */
  OK(eoir_state_load(e, at("good.scd")));

  /* a stale temporary of a killed save is removed; a held one is kept */
  {
    int held;
    write_text(at("good.scd.tmp.Stale1"), "half a state");
    write_text(at("good.scd.tmp.Held22"), "a writer is still here");
    write_text(at("good.scd.tmp.other"), "not our pattern (5 characters)");
    held = open(at("good.scd.tmp.Held22"), O_RDONLY);
    CHECK(held >= 0 && flock(held, LOCK_EX) == 0);
    OK(eoir_state_save(e, at("good.scd")));
    CHECK(!exists(at("good.scd.tmp.Stale1")));
    CHECK(exists(at("good.scd.tmp.Held22")));
    CHECK(exists(at("good.scd.tmp.other")));
    if (held >= 0) close(held);
    OK(eoir_state_save(e, at("good.scd")));
    CHECK(!exists(at("good.scd.tmp.Held22")));
  }

  /* modes: a private file stays private; a new file gets 0666 & ~umask */
  OK(eoir_state_save(e, at("private.scd")));
  CHECK(stat(at("private.scd"), &st) == 0 && (st.st_mode & 07777) == 0644);
  CHECK(chmod(at("private.scd"), 0600) == 0);
  OK(eoir_state_save(e, at("private.scd")));
  CHECK(stat(at("private.scd"), &st) == 0 && (st.st_mode & 07777) == 0600);
  CHECK(chmod(at("good.json"), 0640) == 0);
  OK(eoir_sensor_save(e, "Cam", at("good.json")));
  CHECK(stat(at("good.json"), &st) == 0 && (st.st_mode & 07777) == 0640);

  /* symbolic links are written through */
  CHECK(mkdir(at("real"), 0755) == 0);
  write_text(at("real/state.scd"), "old");
  CHECK(chmod(at("real/state.scd"), 0600) == 0);
  CHECK(symlink("real/state.scd", at("link.scd")) == 0);
  OK(eoir_state_save(e, at("link.scd")));
  CHECK(lstat(at("link.scd"), &st) == 0 && S_ISLNK(st.st_mode));
  CHECK(stat(at("real/state.scd"), &st) == 0 && S_ISREG(st.st_mode) && (st.st_mode & 07777) == 0600);
  {
    char* through = read_text(at("real/state.scd"));
    CHECK(through != NULL && strstr(through, "\"eoir-scd\"") != NULL);
    free(through);
  }
  OK(eoir_state_load(e, at("link.scd")));
  CHECK(symlink("real/new.scd", at("dangling.scd")) == 0);
  OK(eoir_state_save(e, at("dangling.scd")));
  CHECK(lstat(at("dangling.scd"), &st) == 0 && S_ISLNK(st.st_mode) && exists(at("real/new.scd")));

  eoir_engine_destroy(e);
  free(scd);
  free(sensor);
  {
    char cmd[4400];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
  }
  return CHECK_SUMMARY();
}
