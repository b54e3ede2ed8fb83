/* Mesh targets through the C ABI (issue 22 item 4; spec 4.1.5), C99: shape
 * mesh with its file in mesh_file and its scale in dimensions_m. Bad meshes
 * (empty, NaN vertices, degenerate triangles, non-manifold edges, missing
 * files, unknown formats) are refused with a status and a message naming
 * the property, the file and the problem, and leave the object as it was;
 * a good one renders where the same cube as a box does, and a state save
 * and restore reads it back. */
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

static const char* file(const char* name, const char* text) {
  const char* path = at(name);
  write_text(path, text);
  return path;
}

/* The cube [-0.5, 0.5]^3. */
static const char* cube_obj =
    "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv -0.5 0.5 -0.5\nv 0.5 0.5 -0.5\n"
    "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv -0.5 0.5 0.5\nv 0.5 0.5 0.5\n"
    "f 1 3 2\nf 2 3 4\nf 5 6 7\nf 6 8 7\nf 1 2 5\nf 2 6 5\nf 3 7 4\nf 4 7 8\nf 1 5 3\nf 3 5 7\nf 2 4 6\nf 4 8 6\n";

/* The sum of the camera's scene radiance image. */
static double radiance_sum(eoir_engine e) {
  static double values[32 * 32]; /* 8 x 8 pixels of 4 x 4 samples */
  double sum = 0;
  size_t i;
  OK(eoir_render(e, "Cam"));
  OK(eoir_image_get(e, "Cam", EOIR_IMAGE_SCENE_RADIANCE, values, 32 * 32));
  for (i = 0; i < 32 * 32; ++i) sum += values[i];
  return sum;
}

int main(void) {
  eoir_engine e = NULL;
  char text[8192];
  double box_sum, mesh_sum, restored_sum;
  const double scale = 40.0;

  snprintf(dir, sizeof dir, "%s/eoir_mesh_files_XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
  if (mkdtemp(dir) == NULL) return perror("mkdtemp"), 2;

  OK(eoir_engine_create(NULL, &e));
  /* A host satellite looking along +z at a target 10 km away (8 x 8 pixels). */
  host_camera(e, "2010-03-20T12:00:00Z", 8, 8.0, 12.0);
  OK(eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat"));
  OK(put_j2000(e, "Host", 5.0e7, 0, 0));
  OK(put_j2000(e, "Sat", 5.0e7, 0, 1.0e4));
  OK(eoir_set_string(e, "Sat", "shape", "box"));
  OK(eoir_set_array(e, "Sat", "dimensions_m", (const double[]){40.0, 40.0, 40.0}, 3));
  box_sum = radiance_sum(e);
  CHECK(box_sum > 0);

  /* Shape mesh without a file images nothing it cannot read: refused at render. */
  OK(eoir_set_string(e, "Sat", "shape", "mesh"));
  FAILS(eoir_render(e, "Cam"), EOIR_ERR_NOT_ALLOWED, "mesh_file");

  /* Bad files: the status, the property, the file and the problem. */
  FAILS(eoir_set_string(e, "Sat", "mesh_file", file("empty.obj", "# no faces\n")), EOIR_ERR_CORRUPT_FILE,
        "empty.obj': no triangles");
  FAILS(eoir_set_string(e, "Sat", "mesh_file", file("nan.obj", "v 0 0 0\nv 1 0 NaN\nv 0 1 0\nf 1 2 3\n")),
        EOIR_ERR_CORRUPT_FILE, "vertex 1 is not finite");
  FAILS(eoir_set_string(e, "Sat", "mesh_file",
                        file("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")),
        EOIR_ERR_CORRUPT_FILE, "triangle 0 is degenerate");
  FAILS(eoir_set_string(e, "Sat", "mesh_file",
                        file("fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 2 5\n")),
        EOIR_ERR_CORRUPT_FILE, "non-manifold");
  FAILS(eoir_set_string(e, "Sat", "mesh_file", at("missing.glb")), EOIR_ERR_IO, "mesh_file: mesh file '");
  FAILS(eoir_set_string(e, "Sat", "mesh_file", file("model.3ds", "x")), EOIR_ERR_OUT_OF_RANGE, "unknown format");
  FAILS(eoir_set_string(e, "Sat", "mesh_file", file("cut.gltf", "{\"asset\": {\"vers")), EOIR_ERR_CORRUPT_FILE,
        "cut.gltf': not a readable glTF file");
  FAILS(eoir_set_string(e, "Sat", "mesh_file", dir), EOIR_ERR_OUT_OF_RANGE, "unknown format");
  FAILS(eoir_set_string(e, "Sat", "mesh_materials", "{\"hull\": {\"temperature_K\": -1}}"), EOIR_ERR_OUT_OF_RANGE,
        "mesh_materials.hull.temperature_K");
  FAILS(eoir_set_string(e, "Sat", "mesh_materials", "{\"hull\": {\"colour\": 1}}"), EOIR_ERR_UNKNOWN_NAME,
        "mesh_materials.hull.colour");
  FAILS(eoir_set_string(e, "Sat", "composite", "[{\"shape\": \"mesh\", \"dimensions_m\": [1]}]"),
        EOIR_ERR_OUT_OF_RANGE, "composite[0].mesh_file");
  /* A refused file left the object as it was: still no mesh. */
  OK(eoir_get_string(e, "Sat", "mesh_file", text, sizeof text));
  CHECK(strcmp(text, "") == 0);

  /* The cube as a 40 m mesh images as the 40 m box (same hits: 1e-9). */
  OK(eoir_set_string(e, "Sat", "mesh_file", file("cube.obj", cube_obj)));
  OK(eoir_set_array(e, "Sat", "dimensions_m", &scale, 1));
  mesh_sum = radiance_sum(e);
  CHECK(fabs(mesh_sum / box_sum - 1.0) < 1e-9);

  /* Saved and restored, the mesh is read back from its file. */
  OK(eoir_state_save(e, at("mesh.scd")));
  eoir_engine_destroy(e);
  e = NULL;
  OK(eoir_engine_create(NULL, &e));
  OK(eoir_state_load(e, at("mesh.scd")));
  OK(eoir_get_string(e, "Sat", "mesh_file", text, sizeof text));
  CHECK(strcmp(text, at("cube.obj")) == 0);
  restored_sum = radiance_sum(e);
  CHECK(restored_sum == mesh_sum);

  eoir_engine_destroy(e);
  printf("mesh_files: box %.9e, mesh %.9e, restored %.9e; %d checks, %d failures\n", box_sum, mesh_sum, restored_sum,
         check_count, check_failures);
  return check_failures ? 1 : 0;
}
