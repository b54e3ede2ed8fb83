/* Bad star catalogue CSV files through the C ABI (issue 11, item 8; README
 * "Stars"), C99: the star field's catalog_file is read and checked when set;
 * NaN, a missing column, a truncated line, a NUL byte or a file over 256 MiB
 * is EOIR_ERR_CORRUPT_FILE with a message naming the file, the line and the
 * field; a missing file is EOIR_ERR_IO naming the path. A refused file leaves
 * the star field as it was; a good one renders. */
#define _XOPEN_SOURCE 700
#include <stdlib.h>
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

static const char* header = "id,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,parallax_mas,v_mag,b_v\n";

/* A catalogue of the header and `rows`; returns its path. */
static const char* catalogue(const char* file, const char* rows) {
  char text[1024];
  snprintf(text, sizeof text, "%s%s", header, rows);
  write_text(at(file), text);
  return at(file);
}

int main(void) {
  eoir_engine e = NULL;
  char name[4200];
  snprintf(dir, sizeof dir, "%s/eoir_catalog_files_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (mkdtemp(dir) == NULL) return perror("mkdtemp"), 2;

  OK(eoir_engine_create(NULL, &e));
  OK(eoir_object_add(e, EOIR_KIND_STAR_FIELD, "Stars"));
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Host"));
  OK(eoir_set_string(e, "Host", "shape", "none"));
  OK(eoir_sensor_add(e, "Cam", "Host"));
  OK(eoir_set_integer(e, "Cam", "horizontal_pixels", 8));
  OK(eoir_set_integer(e, "Cam", "vertical_pixels", 8));
  OK(put_j2000(e, "Host", 4.2e7, 0, 0));

  OK(eoir_set_string(e, "Stars", "catalog_file", catalogue("good.csv", "vega,279.234735,38.783689,200.94,286.23,130.23,0.03,0.00\n")));
  FAILS(eoir_set_string(e, "Stars", "catalog_file", catalogue("nan.csv", "a,10,10,0,0,1,NaN,0.5\n")), EOIR_ERR_CORRUPT_FILE,
        "nan.csv:2: v_mag: 'NaN' is not a finite number");
  write_text(at("columns.csv"), "id,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,v_mag,b_v\n");
  FAILS(eoir_set_string(e, "Stars", "catalog_file", at("columns.csv")), EOIR_ERR_CORRUPT_FILE,
        "columns.csv:1: parallax_mas: missing column");
  FAILS(eoir_set_string(e, "Stars", "catalog_file", catalogue("truncated.csv", "a,10,10,0,0,1,5,0.5\nb,10,10,0,")),
        EOIR_ERR_CORRUPT_FILE, "truncated.csv:3: line: 5 fields, the header has 8");
  FAILS(eoir_set_string(e, "Stars", "catalog_file", catalogue("range.csv", "a,10,91,0,0,1,5,0.5\n")),
        EOIR_ERR_CORRUPT_FILE, "range.csv:2: dec_deg: 91 outside");
  {
    /* a NUL byte: not text */
    FILE* f = fopen(at("nul.csv"), "wb");
    CHECK(f != NULL);
    if (f) {
      fputs(header, f);
      fwrite("a,10\0x,10,0,0,1,5,0.5\n", 1, 22, f);
      fclose(f);
    }
    FAILS(eoir_set_string(e, "Stars", "catalog_file", at("nul.csv")), EOIR_ERR_CORRUPT_FILE, "nul.csv:2: line: a NUL byte");
  }
  {
    /* a sparse 257 MiB file: refused by its size, not read */
    FILE* f = fopen(at("huge.csv"), "wb");
    CHECK(f != NULL && fseek(f, 257L << 20, SEEK_SET) == 0 && fputc('\n', f) != EOF);
    if (f) fclose(f);
    FAILS(eoir_set_string(e, "Stars", "catalog_file", at("huge.csv")), EOIR_ERR_CORRUPT_FILE,
          "huge.csv' is larger than 256 MiB");
  }
  FAILS(eoir_set_string(e, "Stars", "catalog_file", at("absent.csv")), EOIR_ERR_IO, "absent.csv");
  /* Issue 25, item 2: an id that is not UTF-8 (Latin-1 e-acute) was
   * accepted and aborted the CLI's run when its truth was written. */
  FAILS(eoir_set_string(e, "Stars", "catalog_file", catalogue("latin1.csv", "caf\xe9,10,10,0,0,1,5,0.5\n")),
        EOIR_ERR_CORRUPT_FILE, "latin1.csv:2: id: not valid UTF-8 at byte 3");
  /* Issue 25 item 11: a subnormal is a number (it was "'5e-324' is not a
   * number"); a UTF-8 byte-order mark before the header is accepted (it was
   * "id: missing column"). */
  OK(eoir_set_string(e, "Stars", "catalog_file", catalogue("subnormal.csv", "a,10,10,5e-324,-5e-324,1e-310,5,0.5\n")));
  write_text(at("bom.csv"), "\xEF\xBB\xBFid,ra_deg,dec_deg,pm_ra_mas_yr,pm_dec_mas_yr,parallax_mas,v_mag,b_v\n"
                            "a,10,10,0,0,1,5,0.5\n");
  OK(eoir_set_string(e, "Stars", "catalog_file", at("bom.csv")));
  FAILS(eoir_set_string(e, "Stars", "catalog_file", catalogue("overflow.csv", "a,10,10,1e999,0,1,5,0.5\n")),
        EOIR_ERR_CORRUPT_FILE, "overflow.csv:2: pm_ra_mas_yr: '1e999' is not a finite number");
  OK(eoir_set_string(e, "Stars", "catalog_file", at("good.csv")));

  /* the refusals left the good catalogue in place, and it renders */
  OK(eoir_get_string(e, "Stars", "catalog_file", name, sizeof name));
  CHECK(strcmp(name, at("good.csv")) == 0);
  OK(eoir_render(e, "Cam"));

  {
    /* Issue 25, item 2: a valid id longer than eoir_truth.object's 63 bytes
     * is cut at a character boundary, not inside the 2-byte e-acute at
     * bytes 62-63 (which left invalid UTF-8 in the truth). */
    char id[80], rows[256];
    eoir_image_info info;
    eoir_truth t;
    size_t n = 0, i;
    int found = 0;
    memset(&info, 0, sizeof info);
    info.struct_size = sizeof info;
    OK(eoir_image_info_get(e, "Cam", EOIR_IMAGE_SENSOR_MEAN, &info));
    memset(id, 'a', 62);
    strcpy(id + 62, "\xc3\xa9toile");
    snprintf(rows, sizeof rows, "%s,%.9f,%.9f,0,0,0,5,0.6\n", id, info.boresight_ra_deg, info.boresight_dec_deg);
    OK(eoir_set_string(e, "Stars", "catalog_file", catalogue("long_id.csv", rows)));
    OK(eoir_render(e, "Cam"));
    OK(eoir_truth_count(e, "Cam", &n));
    for (i = 0; i < n; ++i) {
      memset(&t, 0, sizeof t);
      t.struct_size = sizeof t;
      OK(eoir_truth_get(e, "Cam", i, &t));
      if (t.kind != EOIR_TRUTH_STAR) continue;
      found = 1;
      CHECK(strlen(t.object) == 62 && memcmp(t.object, id, 62) == 0);
    }
    CHECK(found);
  }

  eoir_engine_destroy(e);
  {
    char cmd[4200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
  }
  return CHECK_SUMMARY();
}
