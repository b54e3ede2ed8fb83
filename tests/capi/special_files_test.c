/* FIFOs and devices at the paths the engine reads and writes (issue 25,
 * items 3 and 6), C99:
 *  - every file the engine reads (star catalogue, state, sensor and material
 *    files) must be a regular file: a FIFO is refused at once with
 *    EOIR_ERR_IO naming the path (it used to block forever), and so is a
 *    device such as /dev/zero;
 *  - a save does not replace a FIFO at its target (it used to rename a
 *    regular file over it): EOIR_ERR_IO naming the path, the FIFO stays. */
#define _XOPEN_SOURCE 700
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"

static char dir[4096];

static const char* at(const char* name) {
  static char buf[4][4200];
  static int k = 0;
  k = (k + 1) % 4;
  snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
  return buf[k];
}

static int is_fifo(const char* path) {
  struct stat st;
  return lstat(path, &st) == 0 && S_ISFIFO(st.st_mode);
}

int main(void) {
  eoir_engine e = NULL;
  snprintf(dir, sizeof dir, "%s/eoir_special_files_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (mkdtemp(dir) == NULL) return perror("mkdtemp"), 2;
  alarm(120); /* a hang (opening a FIFO without a writer) fails instead of blocking */
  if (mkfifo(at("fifo"), 0600) != 0) return perror("mkfifo"), 2;

  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_sensor_add(e, "Cam", "Sat"));

  /* reads */
  FAILS(eoir_set_string(e, "Stars", "catalog_file", at("fifo")), EOIR_ERR_IO, "fifo' is not a regular file (a FIFO)");
  FAILS(eoir_state_load(e, at("fifo")), EOIR_ERR_IO, "fifo' is not a regular file (a FIFO)");
  FAILS(eoir_sensor_load(e, "Cam", at("fifo")), EOIR_ERR_IO, "fifo' is not a regular file (a FIFO)");
  FAILS(eoir_material_load(e, at("fifo")), EOIR_ERR_IO, "fifo' is not a regular file (a FIFO)");
  FAILS(eoir_set_string(e, "Stars", "catalog_file", "/dev/zero"), EOIR_ERR_IO,
        "'/dev/zero' is not a regular file (a character device)");
  FAILS(eoir_state_load(e, "/dev/zero"), EOIR_ERR_IO, "'/dev/zero' is not a regular file (a character device)");
  FAILS(eoir_set_string(e, "Stars", "catalog_file", dir), EOIR_ERR_IO, "is not a regular file (a directory)");

  /* writes: the FIFO is not replaced */
  FAILS(eoir_state_save(e, at("fifo")), EOIR_ERR_IO, "fifo' is not a regular file (a FIFO)");
  CHECK(is_fifo(at("fifo")));
  FAILS(eoir_sensor_save(e, "Cam", at("fifo")), EOIR_ERR_IO, "fifo' is not a regular file (a FIFO)");
  CHECK(is_fifo(at("fifo")));
  /* nor through a symbolic link, which saves write through */
  CHECK(symlink(at("fifo"), at("link.scd")) == 0);
  FAILS(eoir_state_save(e, at("link.scd")), EOIR_ERR_IO, "fifo' is not a regular file (a FIFO)");
  CHECK(is_fifo(at("fifo")));

  /* regular files still load and save */
  OK(eoir_state_save(e, at("good.scd")));
  OK(eoir_state_load(e, at("good.scd")));

  eoir_engine_destroy(e);
  remove(at("good.scd"));
  remove(at("link.scd"));
  remove(at("fifo"));
  rmdir(dir);
  return CHECK_SUMMARY();
}
