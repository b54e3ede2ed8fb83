// Shapes of spec 4.1.5.1: the simple shapes with the dimensions each takes
// (metres), shape none, composites of simple shapes at offsets and
// orientations, and meshes read from 3-D model files (universe/mesh_model.hpp)
// with a scale. A shape is parsed into its typed kind when the property is
// set; nothing downstream compares names.
#pragma once
#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "universe/mesh_model.hpp"

namespace eoir::universe {

enum class ShapeKind : int { sphere, oblate, box, plate, cylinder, cone, coupler, none, composite, mesh, plume };

struct ShapeInfo {
  ShapeKind kind;
  const char* name;
  std::vector<const char*> dimensions;  // meaning of each entry of dimensions_m
};

// sphere, oblate, box, plate, cylinder, cone, coupler, none, composite, mesh, plume.
const std::vector<ShapeInfo>& shapes();
const ShapeInfo& shape_info(ShapeKind kind);
// Throws eoir::Error(unknown_name) naming `field` with the list of shapes.
ShapeKind parse_shape(const std::string& name, const std::string& field);
// Throws eoir::Error(out_of_range) unless dims fits the shape (count, each
// within object_bounds' lengths; a plume's length above twice its radius).
void check_dimensions(ShapeKind kind, const std::vector<double>& dims, const std::string& field);

// One simple shape placed in its object's body frame (a composite's part, or
// the whole of a simple object), with the surface values it overrides.
struct ShapePart {
  ShapeKind kind = ShapeKind::sphere;
  std::vector<double> dimensions_m{1.0};
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();              // part origin in the body frame
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // part -> body
  std::optional<double> temperature_K;  // else the object's
  std::optional<double> reflectance;    // else the object's
  std::optional<std::string> material;  // else the object's
  // Shape mesh: the model (dimensions_m = [scale], metres per file unit) and
  // the one material group of it this part is (shape_parts splits a mesh).
  std::string mesh_file;
  std::shared_ptr<const MeshModel> mesh;
  std::int32_t mesh_group = -1;  // -1: every group (before the split)
  std::optional<std::string> spectrum;  // a tabulated self-radiance (spectrum table) instead of eps B(T); else the object's
};

// What a mesh file's material (by its name in the file) becomes: an engine
// material, a temperature, a gray-body reflectance; unset: the object's.
struct MeshMaterial {
  std::optional<std::string> material;
  std::optional<double> temperature_K;
  std::optional<double> reflectance;
};
using MeshMaterials = std::map<std::string, MeshMaterial>;

// A whole-mesh part as one part per material group of its model, each with
// the overrides `materials` gives its group's name (on top of the part's own).
std::vector<ShapePart> split_mesh(const ShapePart& part, const MeshMaterials& materials);

}  // namespace eoir::universe
