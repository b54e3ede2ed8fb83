// Mesh targets (shape mesh): the readers' checks, the welded and oriented
// model, and the ray casting, containment and patches of a mesh against the
// analytic box the same cube is (spec 4.1.3, 4.1.5).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "../support/mesh_files.hpp"
#include "core/error.hpp"
#include "geometry/projected_area.hpp"
#include "geometry/scene_geometry.hpp"
#include "universe/composite.hpp"
#include "universe/mesh_model.hpp"

namespace g = eoir::geometry;
namespace u = eoir::universe;
using eoir::Status;
using eoir::test::TriangleMesh;

namespace {

std::string temp_dir() {
  static const std::string dir = [] {
    const auto p = std::filesystem::temp_directory_path() / ("eoir_mesh_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return p.string();
  }();
  return dir;
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = temp_dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

std::string obj_file(const std::string& name, const TriangleMesh& m, const std::string& material = "") {
  const std::string path = temp_dir() + "/" + name;
  eoir::test::write_obj(path, m, material);
  return path;
}

// The status and message of reading a mesh file.
std::pair<Status, std::string> refusal(const std::string& path) {
  try {
    u::load_mesh(path, "mesh_file");
  } catch (const eoir::Error& e) {
    return {e.status(), e.what()};
  }
  return {Status::ok, ""};
}

g::ShapePart mesh_part(const std::string& path, double scale, std::int32_t group = 0) {
  u::ShapePart p;
  p.kind = u::ShapeKind::mesh;
  p.dimensions_m = {scale};
  p.mesh = u::load_mesh(path, "mesh_file");
  p.mesh_group = group;
  return g::make_part(p);
}

}  // namespace

TEST(MeshModel, CubeIsClosedWeldedAndOrientedOutward) {
  TriangleMesh cube = eoir::test::unit_cube();
  std::swap(cube.triangles[3][1], cube.triangles[3][2]);  // one face turned inward
  const auto m = u::load_mesh(obj_file("cube_flipped.obj", cube), "mesh_file");
  EXPECT_TRUE(m->closed);
  EXPECT_EQ(m->vertices.size(), 8u);
  EXPECT_EQ(m->triangles.size(), 12u);
  EXPECT_NEAR(m->volume, 1.0, 1e-12);  // the unit cube
  // Every triangle's normal points away from the centre.
  for (const auto& t : m->triangles) {
    const Eigen::Vector3d a = m->vertices[t[0]], b = m->vertices[t[1]], c = m->vertices[t[2]];
    EXPECT_GT((b - a).cross(c - a).dot((a + b + c) / 3.0), 0.0);
  }
}

TEST(MeshModel, GltfAndObjGiveTheSameModel) {
  const std::string gltf = temp_dir() + "/cube.gltf";
  eoir::test::write_gltf(gltf, eoir::test::unit_cube());
  const auto a = u::load_mesh(gltf, "mesh_file");
  const auto b = u::load_mesh(obj_file("cube.obj", eoir::test::unit_cube()), "mesh_file");
  EXPECT_EQ(a->triangles.size(), b->triangles.size());
  EXPECT_EQ(a->vertices.size(), b->vertices.size());
  EXPECT_NEAR(a->volume, b->volume, 1e-12);
  ASSERT_EQ(a->group_materials.size(), 1u);
  EXPECT_EQ(a->group_materials[0], "hull");
}

TEST(MeshModel, IcosphereOf20480Triangles) {
  const auto m = u::load_mesh(obj_file("ico5.obj", eoir::test::icosphere(5)), "mesh_file");
  EXPECT_EQ(m->triangles.size(), 20480u);
  EXPECT_TRUE(m->closed);
  // Inscribed in the unit sphere: a little less than 4 pi / 3.
  EXPECT_LT(m->volume, 4.0 * M_PI / 3.0);
  EXPECT_NEAR(m->volume / (4.0 * M_PI / 3.0), 1.0, 2e-3);
}

TEST(MeshModel, OpenSheetIsTwoSided) {
  const auto m = u::load_mesh(write("sheet.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n"), "mesh_file");
  EXPECT_FALSE(m->closed);
  EXPECT_EQ(m->triangle_closed, (std::vector<std::uint8_t>{0, 0}));
  const g::ShapePart part = mesh_part(m->file, 2.0);
  // Seen from both sides, both faces counted (as the plate).
  EXPECT_NEAR(g::shape_surface_area_m2(part.geom), 2.0 * 4.0, 1e-12);
  const g::Tessellation t = g::tessellate({part}, 1.0);
  EXPECT_EQ(t.patches.size(), 4u);
  double t_hit = 0;
  Eigen::Vector3d n;
  ASSERT_TRUE(g::intersect_shape(part.geom, {0.5, 0.5, -3}, {0, 0, 1}, 0, 1e30, t_hit, n));
  EXPECT_NEAR(t_hit, 3.0, 1e-12);
  EXPECT_EQ(n, Eigen::Vector3d(0, 0, -1));  // toward the ray
  ASSERT_TRUE(g::intersect_shape(part.geom, {0.5, 0.5, 3}, {0, 0, -1}, 0, 1e30, t_hit, n));
  EXPECT_EQ(n, Eigen::Vector3d(0, 0, 1));
  EXPECT_FALSE(g::shape_contains(part.geom, {1, 1, 0}));
}

TEST(MeshModel, MaterialsMakeGroups) {
  const std::string mtl = write("two.mtl", "newmtl gold\nKd 1 1 0\nnewmtl black\nKd 0 0 0\n");
  (void)mtl;
  const std::string path = write("two.obj",
                                 "mtllib two.mtl\nv -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv -0.5 0.5 -0.5\nv 0.5 0.5 -0.5\n"
                                 "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv -0.5 0.5 0.5\nv 0.5 0.5 0.5\n"
                                 "usemtl gold\nf 1 3 2\nf 2 3 4\nf 5 6 7\nf 6 8 7\nf 1 2 5\nf 2 6 5\n"
                                 "usemtl black\nf 3 7 4\nf 4 7 8\nf 1 5 3\nf 3 5 7\nf 2 4 6\nf 4 8 6\n");
  const auto m = u::load_mesh(path, "mesh_file");
  ASSERT_EQ(m->group_materials, (std::vector<std::string>{"gold", "black"}));
  // Without its .mtl file (a quad face too: two triangles), usemtl still names the groups.
  const auto bare = u::load_mesh(write("bare.obj",
                                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nusemtl hull\nf 1 2 3 4\n"
                                       "usemtl panel\nf 1 2 5\n"),
                                 "mesh_file");
  ASSERT_EQ(bare->group_materials, (std::vector<std::string>{"hull", "panel"}));
  EXPECT_EQ(bare->triangle_group, (std::vector<std::int32_t>{0, 0, 1}));
  EXPECT_TRUE(m->closed);  // the groups together are watertight
  // The composite splits it into one part per group, mapped to surfaces.
  const auto parts = u::parse_composite(
      R"([{"shape": "mesh", "mesh_file": ")" + path +
          R"(", "dimensions_m": [2], "mesh_materials": {"gold": {"material": "gold_mli", "temperature_K": 350}}}])",
      "composite");
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].material.value_or(""), "gold_mli");
  EXPECT_EQ(parts[0].temperature_K.value_or(0), 350.0);
  EXPECT_FALSE(parts[1].material.has_value());
  // Each part's volume share sums to the whole (2 m cube: 8 m^3).
  double volume = 0;
  for (std::int32_t k = 0; k < 2; ++k) {
    const g::ShapePart p = mesh_part(path, 2.0, k);
    volume += p.geom.mesh->volume_m3(k);
    EXPECT_NEAR(g::shape_surface_area_m2(p.geom), 12.0, 1e-12);  // 3 faces of 4 m^2 each
  }
  EXPECT_NEAR(volume, 8.0, 1e-12);
}

TEST(MeshModel, BadMeshesNameTheFileAndTheProblem) {
  const auto expect = [](const std::string& path, Status status, const std::string& problem) {
    const auto [s, message] = refusal(path);
    EXPECT_EQ(s, status) << path << ": " << message;
    EXPECT_NE(message.find("mesh_file"), std::string::npos) << message;
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message;
  };
  expect(write("empty.obj", "# nothing\n"), Status::corrupt_file, "no triangles");
  expect(write("nan.obj", "v 0 0 0\nv 1 0 nan\nv 0 1 0\nf 1 2 3\n"), Status::corrupt_file, "vertex 1 is not finite");
  expect(write("degenerate.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n"), Status::corrupt_file,
         "triangle 0 is degenerate");
  expect(write("fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 2 5\n"),
         Status::corrupt_file, "non-manifold");
  expect(write("bad_index.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n"), Status::corrupt_file, "");
  expect(temp_dir() + "/missing.obj", Status::io, "No such file");
  expect(write("model.stl", "solid x\n"), Status::out_of_range, "unknown format");
  expect(write("broken.gltf", "{\"asset\": "), Status::corrupt_file, "not a readable glTF file");
  // A glTF that claims more triangles than the limit is refused before its
  // buffer is read.
  expect(write("huge.gltf",
               R"({"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
               {"bufferView": 1, "componentType": 5125, "count": 30000000, "type": "SCALAR"}],
 "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12}],
 "buffers": [{"byteLength": 48, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAEAAAACAAAA"}]})"),
         Status::limit_exceeded, "4000000 triangles");
}

// The mesh cube and the box: the same hits (range to 1e-12 relative, the
// same normal) from random rays, near and at 40,000 km.
TEST(MeshGeometry, CubeHitsAsTheBox) {
  const g::ShapePart mesh = mesh_part(obj_file("cube2.obj", eoir::test::unit_cube()), 3.0);
  const g::ShapeGeom box = g::shape_geom(u::ShapeKind::box, {3.0, 3.0, 3.0});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  int hits = 0;
  for (double range : {10.0, 4.0e7}) {
    for (int i = 0; i < 2000; ++i) {
      Eigen::Vector3d o(uni(rng), uni(rng), uni(rng));
      o = range * o.normalized();
      const Eigen::Vector3d aim(1.6 * uni(rng), 1.6 * uni(rng), 1.6 * uni(rng));
      const Eigen::Vector3d d = (aim - o).normalized();
      double t1 = 0, t2 = 0;
      Eigen::Vector3d n1, n2;
      const bool h1 = g::intersect_shape(mesh.geom, o, d, 0, 1e30, t1, n1);
      const bool h2 = g::intersect_shape(box, o, d, 0, 1e30, t2, n2);
      // (rays within float rounding of an edge may differ; none of these do)
      ASSERT_EQ(h1, h2) << i << " at " << range;
      if (!h1) continue;
      ++hits;
      EXPECT_NEAR(t1, t2, 1e-12 * range + 1e-12) << i;
      EXPECT_NEAR((n1 - n2).norm(), 0.0, 1e-12) << i;
    }
  }
  EXPECT_GT(hits, 1000);
  EXPECT_TRUE(g::shape_contains(mesh.geom, {0.3, -0.2, 1.4}));
  EXPECT_FALSE(g::shape_contains(mesh.geom, {0.3, -0.2, 1.6}));
  EXPECT_NEAR(g::shape_bounding_radius_m(mesh.geom), g::shape_bounding_radius_m(box), 1e-12);
  EXPECT_NEAR(g::shape_surface_area_m2(mesh.geom), 54.0, 1e-12);
}

// Patches: one per triangle of a closed mesh; the patch of a surface point is
// its triangle's; the projected area (eq. 58) of the facing patches equals
// the box's closed form.
TEST(MeshGeometry, PatchesAndProjectedArea) {
  const g::ShapePart mesh = mesh_part(obj_file("cube3.obj", eoir::test::unit_cube()), 2.0);
  const std::vector<g::ShapePart> parts{mesh};
  const g::Tessellation t = g::tessellate(parts, 0.1);  // (the target does not split triangles)
  ASSERT_EQ(t.patches.size(), 12u);
  for (std::size_t k = 0; k < t.patches.size(); ++k)
    EXPECT_EQ(g::patch_at_facing(t, parts, 0, t.patches[k].centre_body_m, t.patches[k].normal_body),
              static_cast<std::int32_t>(k));
  const Eigen::Vector3d v = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const g::ShapePart box{g::shape_geom(u::ShapeKind::box, {2.0, 2.0, 2.0})};
  EXPECT_NEAR(g::projected_area_m2(parts, t, v), g::analytic_projected_area_m2(box, v), 1e-12);
}

// The hierarchy is built once per model and scale (not per frame or per
// part): every part made from them shares it while the model lives.
TEST(MeshGeometry, BuiltOncePerModelAndScale) {
  const auto model = u::load_mesh(obj_file("cube4.obj", eoir::test::unit_cube()), "mesh_file");
  const auto a = g::MeshGeometry::of(model, 2.0), b = g::MeshGeometry::of(model, 2.0);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_NE(g::MeshGeometry::of(model, 3.0).get(), a.get());
  // Read again unchanged, the file gives the same model (and so the same hierarchy).
  EXPECT_EQ(u::load_mesh(model->file, "mesh_file").get(), model.get());
}
