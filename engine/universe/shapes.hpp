// Shapes of spec 4.1.5.1: the simple shapes with the dimensions each takes
// (metres), shape none, and composites of simple shapes at offsets and
// orientations. A shape is parsed into its typed kind when the property is
// set; nothing downstream compares names.
#pragma once
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

namespace eoir::universe {

enum class ShapeKind : int {
  sphere,
  oblate,
  box,
  plate,
  cylinder,
  cone,
  coupler,
  none,
  composite,
  plume,
};

struct ShapeInfo {
  ShapeKind kind;
  const char* name;
  std::vector<const char*> dimensions;  // meaning of each entry of dimensions_m
};

// sphere, oblate, box, plate, cylinder, cone, coupler, none, composite, plume.
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
  std::optional<std::string> spectrum;  // a tabulated self-radiance (spectrum table) instead of eps B(T); else the object's
};

}  // namespace eoir::universe
