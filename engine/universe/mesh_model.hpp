// A target's shape from a 3-D model file (glTF 2.0 or Wavefront OBJ): its
// triangles in the file's units, welded at equal positions, grouped by the
// file's materials, checked and oriented once when read. The shape `mesh`
// (universe/shapes.hpp) scales it to metres; geometry/mesh_geometry.hpp builds
// its ray-casting hierarchy.
#pragma once
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace eoir::universe {

// The most triangles a mesh may have, and the largest file read (bytes).
constexpr std::size_t max_mesh_triangles = 4'000'000;
constexpr std::size_t max_mesh_file_bytes = std::size_t{1} << 30;
constexpr std::size_t max_mesh_materials = 256;

struct MeshModel {
  std::string file;                                   // as read
  std::vector<Eigen::Vector3d> vertices;              // file units, distinct positions
  std::vector<std::array<std::int32_t, 3>> triangles; // counter-clockwise seen from outside where closed
  std::vector<std::int32_t> triangle_group;           // index into group_materials
  std::vector<std::uint8_t> triangle_closed;          // 1: part of a closed (watertight) piece, one-sided
  std::vector<std::string> group_materials;           // the file's material name of each group ("" none)
  bool closed = false;                                // every piece watertight
  double volume = 0.0;                                // enclosed by the closed pieces (file units^3)
};

// Reads `path` (.gltf, .glb or .obj, by its extension). Throws eoir::Error
// naming `field`, the file and the problem: io (missing, unreadable, not a
// regular file), corrupt_file (not parseable, no triangles, a non-finite
// vertex, a degenerate triangle, an edge shared by more than two triangles or
// a watertight piece that cannot be oriented), limit_exceeded (more than
// max_mesh_triangles or max_mesh_materials, a file larger than
// max_mesh_file_bytes). Pieces whose
// every edge joins two triangles are closed and oriented outward; the others
// are open sheets seen from both sides. A file read before and unchanged
// (size and modification time) is shared, not read again.
std::shared_ptr<const MeshModel> load_mesh(const std::string& path, const std::string& field);

}  // namespace eoir::universe
