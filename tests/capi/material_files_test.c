/* Bad material files through the C ABI (issue 8; spec 4.1.4.1, DESIGN 5
 * "bad input gets a status code and a message naming the field"), C99:
 * eoir_material_load refuses non-monotonic wavelengths, reflectance outside
 * [0, 1], NaN (the bare token Python's json.dump writes, a string, or a
 * number beyond a double), missing or unknown fields and BRDF parameters of
 * eq. 1 out of range with EOIR_ERR_CORRUPT_FILE and a message naming the
 * field and the file; a missing file is EOIR_ERR_IO naming the path; an
 * unknown material name on an object is EOIR_ERR_UNKNOWN_NAME naming the
 * field and the name. Missing arrays, truncated, empty, binary, deeply
 * nested files and duplicated keys name the file and the JSON path (and
 * line) where they fail; files over 16 MiB and devices are refused unread. A refused file adds nothing; a good one is used by
 * the render. */
#define _XOPEN_SOURCE 700
#include <stdlib.h>
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

/* A material file whose brdf object, wavelength and reflectance arrays are
 * given as JSON text. */
static const char* material(const char* file, const char* name, const char* brdf, const char* wavelengths,
                            const char* reflectance, const char* extra) {
  const char* path = at(file);
  FILE* f = fopen(path, "wb");
  if (f == NULL) {
    perror(path);
    exit(2);
  }
  fprintf(f,
          "{\"format\": \"eoir-material\", \"version\": 1, \"name\": \"%s\",\n"
          " \"description\": \"test material\", \"sources\": [\"material_files_test.c\"],\n"
          " \"brdf\": %s,\n \"wavelength_um\": %s,\n \"reflectance\": %s%s}\n",
          name, brdf, wavelengths, reflectance, extra);
  fclose(f);
  return path;
}

static const char* lambert = "{\"k0\": 1.0, \"k1\": 0.0, \"alpha\": 1.0, \"beta\": 1.0}";
static const char* wl4 = "[0.28, 1.0, 10.0, 28.0]";
static const char* r4 = "[0.5, 0.5, 0.5, 0.5]";

int main(void) {
  eoir_engine e = NULL;
  double radiance_good = 0;
  size_t count = 0;

  snprintf(dir, sizeof dir, "%s/eoir_material_files_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (mkdtemp(dir) == NULL) return perror("mkdtemp"), 2;

  OK(eoir_engine_create(NULL, &e));
  /* A host satellite looking along +z at a sphere 10 km away. */
  host_camera(e, "2010-03-20T12:00:00Z", 8, 8.0, 12.0);
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(eoir_set_array(e, "Sat", "dimensions_m", (const double[]){100.0}, 1));
  OK(put_j2000(e, "Host", 5.0e7, 0, 0));
  OK(put_j2000(e, "Sat", 5.0e7, 0, 1.0e4));

  /* A good file loads and the render uses it: emissivity 1 - 0.5. */
  OK(eoir_material_load(e, material("good.json", "test_gray_half", lambert, wl4, r4, "")));
  OK(eoir_set_string(e, "Sat", "material", "test_gray_half"));
  OK(eoir_render(e, "Cam"));
  {
    eoir_pick p;
    memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    OK(eoir_pick_get(e, "Cam", 1, 4, 4, &p, NULL, NULL, 0, &count));
    CHECK(p.hit && strcmp(p.object, "Sat") == 0);
    radiance_good = p.effective_radiance;
    CHECK(radiance_good > 0);
  }

  /* Non-monotonic and non-positive wavelengths. */
  FAILS(eoir_material_load(e, material("nonmono.json", "bad1", lambert, "[0.28, 1.0, 0.9, 28.0]", r4, "")),
        EOIR_ERR_CORRUPT_FILE, "wavelength_um[2]");
  FAILS(eoir_material_load(e, at("nonmono.json")), EOIR_ERR_CORRUPT_FILE, "nonmono.json");
  FAILS(eoir_material_load(e, material("repeat.json", "bad1", lambert, "[0.28, 1.0, 1.0, 28.0]", r4, "")),
        EOIR_ERR_CORRUPT_FILE, "wavelength_um[2]");
  FAILS(eoir_material_load(e, material("negwl.json", "bad1", lambert, "[-0.28, 1.0, 10.0, 28.0]", r4, "")),
        EOIR_ERR_CORRUPT_FILE, "wavelength_um[0]");
  FAILS(eoir_material_load(e, material("count.json", "bad1", lambert, wl4, "[0.5, 0.5, 0.5]", "")),
        EOIR_ERR_CORRUPT_FILE, "reflectance");

  /* Reflectance outside [0, 1]. */
  FAILS(eoir_material_load(e, material("above.json", "bad2", lambert, wl4, "[0.5, 1.2, 0.5, 0.5]", "")),
        EOIR_ERR_CORRUPT_FILE, "reflectance[1]");
  FAILS(eoir_material_load(e, at("above.json")), EOIR_ERR_CORRUPT_FILE, "above.json");
  FAILS(eoir_material_load(e, material("below.json", "bad2", lambert, wl4, "[-0.01, 0.5, 0.5, 0.5]", "")),
        EOIR_ERR_CORRUPT_FILE, "reflectance[0]");

  /* NaN: the bare token (not JSON, but what Python's json.dump writes), a
   * string, Infinity, and a number beyond a double. */
  FAILS(eoir_material_load(e, material("nan.json", "bad3", lambert, wl4, "[0.5, NaN, 0.5, 0.5]", "")),
        EOIR_ERR_CORRUPT_FILE, "reflectance[1]");
  FAILS(eoir_material_load(e, at("nan.json")), EOIR_ERR_CORRUPT_FILE, "nan.json");
  FAILS(eoir_material_load(e, material("nanwl.json", "bad3", lambert, "[0.28, 1.0, NaN, 28.0]", r4, "")),
        EOIR_ERR_CORRUPT_FILE, "wavelength_um[2]");
  FAILS(eoir_material_load(e, material("nanstr.json", "bad3", lambert, wl4, "[0.5, \"NaN\", 0.5, 0.5]", "")),
        EOIR_ERR_CORRUPT_FILE, "reflectance[1]");
  FAILS(eoir_material_load(e, material("inf.json", "bad3", lambert, wl4, "[0.5, 0.5, Infinity, 0.5]", "")),
        EOIR_ERR_CORRUPT_FILE, "reflectance[2]");
  FAILS(eoir_material_load(e, material("huge.json", "bad3", lambert, wl4, "[0.5, 0.5, 0.5, 1e999]", "")),
        EOIR_ERR_CORRUPT_FILE, "reflectance[3]");
  FAILS(eoir_material_load(e, material("nank0.json", "bad3", "{\"k0\": NaN, \"k1\": 0.0, \"alpha\": 1.0, \"beta\": 1.0}",
                                       wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "brdf.k0");

  /* BRDF parameters of eq. 1 out of range, or missing. */
  FAILS(eoir_material_load(e, material("k0.json", "bad4", "{\"k0\": 1.5, \"k1\": 0.0, \"alpha\": 1.0, \"beta\": 1.0}",
                                       wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "brdf.k0");
  FAILS(eoir_material_load(e, at("k0.json")), EOIR_ERR_CORRUPT_FILE, "k0.json");
  FAILS(eoir_material_load(e, material("k1.json", "bad4", "{\"k0\": 0.5, \"k1\": -0.5, \"alpha\": 1.0, \"beta\": 1.0}",
                                       wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "brdf.k1");
  FAILS(eoir_material_load(e, material("alpha.json", "bad4",
                                       "{\"k0\": 0.5, \"k1\": 0.5, \"alpha\": -1.0, \"beta\": 1.0}", wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "brdf.alpha");
  FAILS(eoir_material_load(e, material("beta.json", "bad4",
                                       "{\"k0\": 0.5, \"k1\": 0.5, \"alpha\": 1.0, \"beta\": 1e6}", wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "brdf.beta");
  FAILS(eoir_material_load(e, material("nok1.json", "bad4", "{\"k0\": 0.5, \"alpha\": 1.0, \"beta\": 1.0}", wl4, r4,
                                       "")),
        EOIR_ERR_CORRUPT_FILE, "brdf.k1");

  /* Unknown field, wrong format, missing file. */
  FAILS(eoir_material_load(e, material("unknown.json", "bad5", lambert, wl4, r4, ", \"reflectence\": [1]")),
        EOIR_ERR_CORRUPT_FILE, "reflectence");
  FAILS(eoir_material_load(e, at("no_such_file.json")), EOIR_ERR_IO, "no_such_file.json");

  /* Missing arrays, truncated, empty, duplicated keys, deep nesting, binary,
   * huge files and devices (issue 11, item 8): refused naming the file and
   * where it stops, without reading more than 16 MiB. */
  FAILS(eoir_material_load(e, material("nowl.json", "bad6", lambert, "[0.28, 28.0]", "[0.5, 0.5]",
                                       ", \"wavelength_um\": [1.0, 2.0]")),
        EOIR_ERR_CORRUPT_FILE, "wavelength_um: duplicate key");
  write_text(at("missing.json"), "{\"format\": \"eoir-material\", \"version\": 1, \"name\": \"bad6\", "
                                 "\"sources\": [\"x\"], \"brdf\": {\"k0\": 1, \"k1\": 0, \"alpha\": 1, \"beta\": 1}, "
                                 "\"reflectance\": [0.5, 0.5]}");
  FAILS(eoir_material_load(e, at("missing.json")), EOIR_ERR_CORRUPT_FILE, "wavelength_um");
  FAILS(eoir_material_load(e, at("missing.json")), EOIR_ERR_CORRUPT_FILE, "missing.json");
  write_text(at("truncated.json"), "{\"format\": \"eoir-material\", \"version\": 1, \"name\": \"bad6\",\n"
                                   " \"wavelength_um\": [0.28, 1.0, 1");
  FAILS(eoir_material_load(e, at("truncated.json")), EOIR_ERR_CORRUPT_FILE, "wavelength_um[3]: not valid JSON");
  FAILS(eoir_material_load(e, at("truncated.json")), EOIR_ERR_CORRUPT_FILE, "line 2");
  FAILS(eoir_material_load(e, at("truncated.json")), EOIR_ERR_CORRUPT_FILE, "truncated.json");
  write_text(at("empty.json"), "");
  FAILS(eoir_material_load(e, at("empty.json")), EOIR_ERR_CORRUPT_FILE, "empty.json");
  write_text(at("binary.json"), "\x7f" "ELF\x02\x01\x01");
  FAILS(eoir_material_load(e, at("binary.json")), EOIR_ERR_CORRUPT_FILE, "not valid JSON");
  {
    char deep[2 * 100000 + 1];
    memset(deep, '[', 100000);
    memset(deep + 100000, ']', 100000);
    deep[2 * 100000] = '\0';
    write_text(at("deep.json"), deep);
    FAILS(eoir_material_load(e, at("deep.json")), EOIR_ERR_CORRUPT_FILE, "nested deeper than 64");
  }
  {
    /* a sparse 17 MiB file: refused by its size, not read */
    FILE* f = fopen(at("huge.json"), "wb");
    CHECK(f != NULL && fseek(f, 17L << 20, SEEK_SET) == 0 && fputc('}', f) != EOF);
    if (f) fclose(f);
    FAILS(eoir_material_load(e, at("huge.json")), EOIR_ERR_CORRUPT_FILE, "huge.json' is larger than 16 MiB");
  }
  FAILS(eoir_material_load(e, "/dev/zero"), EOIR_ERR_IO, "'/dev/zero' is not a regular file");
  FAILS(eoir_material_load(e, dir), EOIR_ERR_IO, dir);

  /* None of the refused files added a material: naming one is an unknown
   * name, refused when set (the message names the field and the name, and
   * lists the known materials); so is a name that was never loaded, and the
   * empty name. The object keeps its material. */
  FAILS(eoir_set_string(e, "Sat", "material", "bad2"), EOIR_ERR_UNKNOWN_NAME, "material: unknown material 'bad2'");
  FAILS(eoir_set_string(e, "Sat", "material", "bad3"), EOIR_ERR_UNKNOWN_NAME, "test_gray_half");
  FAILS(eoir_set_string(e, "Sat", "material", "no_such_material"), EOIR_ERR_UNKNOWN_NAME, "'no_such_material'");
  FAILS(eoir_set_string(e, "Sat", "material", ""), EOIR_ERR_UNKNOWN_NAME, "material");
  {
    char name[64];
    OK(eoir_get_string(e, "Sat", "material", name, sizeof name));
    CHECK(strcmp(name, "test_gray_half") == 0);
  }

  /* The engine is unchanged by the refusals: the good material renders the same. */
  OK(eoir_render(e, "Cam"));
  {
    eoir_pick p;
    memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    OK(eoir_pick_get(e, "Cam", 1, 4, 4, &p, NULL, NULL, 0, &count));
    CHECK(p.effective_radiance == radiance_good);
  }

  /* Issue 25 item 1: a state holding a user material, a redefined built-in
   * (aluminum, here a flat 0.5 gray Lambertian) and a user spectrum saves
   * and loads, and the loaded engine renders the same samples bit for bit;
   * saving it again writes the same file. A material file whose optional
   * description is not a string is a corrupt file naming the field. */
  {
    const double wl[2] = {0.28, 28.0}, L[2] = {1e-3, 1e-3};
    eoir_engine loaded = NULL;
    eoir_pick p, q;
    double redefined = 0;
    OK(eoir_material_load(e, material("aluminum.json", "aluminum", lambert, wl4, r4, "")));
    OK(eoir_spectrum_add(e, "glow", wl, L, 2));
    OK(eoir_render(e, "Cam"));
    memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    OK(eoir_pick_get(e, "Cam", 1, 4, 4, &p, NULL, NULL, 0, &count));
    CHECK(p.effective_radiance == radiance_good);
    OK(eoir_state_save(e, at("user.scd")));
    OK(eoir_engine_create(NULL, &loaded));
    OK(eoir_state_load(loaded, at("user.scd")));
    OK(eoir_render(loaded, "Cam"));
    memset(&q, 0, sizeof q);
    q.struct_size = sizeof q;
    OK(eoir_pick_get(loaded, "Cam", 1, 4, 4, &q, NULL, NULL, 0, &count));
    CHECK(q.hit && strcmp(q.object, "Sat") == 0);
    CHECK(q.effective_radiance == radiance_good);
    /* The redefined aluminum is the user's gray 0.5 after the load too: the
     * same radiance as test_gray_half at the same temperature. */
    OK(eoir_set_string(loaded, "Sat", "material", "aluminum"));
    OK(eoir_render(loaded, "Cam"));
    OK(eoir_pick_get(loaded, "Cam", 1, 4, 4, &q, NULL, NULL, 0, &count));
    redefined = q.effective_radiance;
    CHECK(redefined == radiance_good);
    OK(eoir_set_string(loaded, "Sat", "material", "test_gray_half"));
    OK(eoir_set_string(loaded, "Sat", "spectrum", "glow"));
    OK(eoir_render(loaded, "Cam"));
    OK(eoir_set_string(loaded, "Sat", "spectrum", ""));
    OK(eoir_state_save(loaded, at("user2.scd")));
    {
      FILE* a = fopen(at("user.scd"), "rb");
      FILE* b = fopen(at("user2.scd"), "rb");
      int ca = 0, cb = 0;
      CHECK(a != NULL && b != NULL);
      if (a && b) {
        do {
          ca = fgetc(a);
          cb = fgetc(b);
        } while (ca == cb && ca != EOF);
        CHECK(ca == cb);
      }
      if (a) fclose(a);
      if (b) fclose(b);
    }
    eoir_engine_destroy(loaded);
    write_text(at("desc.json"), "{\"format\": \"eoir-material\", \"version\": 1, \"name\": \"desc\", \"description\": 5,\n"
                                " \"sources\": [\"x\"], \"brdf\": {\"k0\": 1, \"k1\": 0, \"alpha\": 1, \"beta\": 1},\n"
                                " \"wavelength_um\": [0.28, 28], \"reflectance\": [0.5, 0.5]}\n");
    FAILS(eoir_material_load(e, at("desc.json")), EOIR_ERR_CORRUPT_FILE, "desc.json: description: expected a string");
    /* Found by fuzz.material_load: a format that is not a string. */
    write_text(at("fmt.json"), "{\"format\": [\"x\"], \"version\": 1, \"name\": \"fmt\", \"sources\": [\"x\"],\n"
                               " \"brdf\": {\"k0\": 1, \"k1\": 0, \"alpha\": 1, \"beta\": 1},\n"
                               " \"wavelength_um\": [0.28, 28], \"reflectance\": [0.5, 0.5]}\n");
    FAILS(eoir_material_load(e, at("fmt.json")), EOIR_ERR_CORRUPT_FILE, "fmt.json: format: must be");
  }

  /* Issue 25 item 8: a table must cover 0.28-28 um, every band a sensor may
   * take (outside it the SRF would be a silent 0: black); the lobes of eq. 1
   * need a sharpness (alpha, beta > 0 as in the schema); names follow the
   * schema's ^[a-z0-9_]+$; the other optional fields are typed. Each is a
   * corrupt file naming the field. */
  FAILS(eoir_material_load(e, material("visible.json", "visible", lambert, "[0.4, 0.7]", "[0.5, 0.5]", "")),
        EOIR_ERR_CORRUPT_FILE, "visible.json: wavelength_um[0]: 0.4 um: the table must cover 0.28-28 um");
  FAILS(eoir_material_load(e, material("short.json", "short_ir", lambert, "[0.28, 1.0, 14.0]", "[0.5, 0.5, 0.5]",
                                       "")),
        EOIR_ERR_CORRUPT_FILE, "short.json: wavelength_um[2]: 14 um: the table must cover 0.28-28 um");
  FAILS(eoir_material_load(e, material("alpha0.json", "flat", "{\"k0\": 0.5, \"k1\": 0.5, \"alpha\": 0, \"beta\": 1}",
                                       wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "alpha0.json: brdf.alpha: must be > 0");
  FAILS(eoir_material_load(e, material("beta0.json", "flat", "{\"k0\": 0.5, \"k1\": 0.5, \"alpha\": 1, \"beta\": 0.0}",
                                       wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "beta0.json: brdf.beta: must be > 0");
  FAILS(eoir_material_load(e, material("upper.json", "Gold-Leaf", lambert, wl4, r4, "")), EOIR_ERR_CORRUPT_FILE,
        "upper.json: name: must be 1 to 63 of a-z, 0-9 and _");
  FAILS(eoir_material_load(e, material("space.json", "gold leaf", lambert, wl4, r4, "")), EOIR_ERR_CORRUPT_FILE,
        "space.json: name");
  FAILS(eoir_material_load(e, material("long.json", "a123456789a123456789a123456789a123456789a123456789a123456789abcd",
                                       lambert, wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "long.json: name");
  FAILS(eoir_material_load(e, material("grid.json", "typed", lambert, wl4, r4, ", \"grid\": 5")), EOIR_ERR_CORRUPT_FILE,
        "grid.json: grid: expected a string");
  FAILS(eoir_material_load(e, material("extension.json", "typed", lambert, wl4, r4, ", \"extension\": [1]")),
        EOIR_ERR_CORRUPT_FILE, "extension.json: extension: expected a string");
  FAILS(eoir_material_load(e, material("reason.json", "typed", "{\"k0\": 1, \"k1\": 0, \"alpha\": 1, \"beta\": 1, \"reason\": 2}",
                                       wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "reason.json: brdf.reason: expected a string");
  FAILS(eoir_material_load(e, material("gloss.json", "typed", "{\"k0\": 1, \"k1\": 0, \"alpha\": 1, \"beta\": 1, \"gloss\": 2}",
                                       wl4, r4, "")),
        EOIR_ERR_CORRUPT_FILE, "gloss.json: brdf.gloss: unknown field");
  FAILS(eoir_material_load(e, material("comp.json", "typed", lambert, wl4, r4,
                                       ", \"composition\": [{\"component\": \"grass\", \"fraction\": 1.5}]")),
        EOIR_ERR_CORRUPT_FILE, "comp.json: composition[0].fraction: must be in [0, 1], got 1.5");
  FAILS(eoir_material_load(e, material("comp2.json", "typed", lambert, wl4, r4, ", \"composition\": {}")),
        EOIR_ERR_CORRUPT_FILE, "comp2.json: composition");
  FAILS(eoir_set_string(e, "Sat", "material", "visible"), EOIR_ERR_UNKNOWN_NAME, "'visible'");
  /* The schema's optional fields, well typed, load. */
  OK(eoir_material_load(e, material("typed.json", "typed_ok",
                                    "{\"k0\": 1, \"k1\": 0, \"alpha\": 1, \"beta\": 1, \"reason\": \"test\"}", wl4,
                                    r4,
                                    ", \"grid\": \"eoir-grid-1\", \"extension\": \"none\", "
                                    "\"composition\": [{\"component\": \"grass\", \"fraction\": 0.5}]")));

  eoir_engine_destroy(e);
  {
    char cmd[4200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    CHECK(system(cmd) == 0);
  }
  return CHECK_SUMMARY();
}
