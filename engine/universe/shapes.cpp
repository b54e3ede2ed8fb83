#include "universe/shapes.hpp"

#include "core/error.hpp"
#include "core/value.hpp"
#include "universe/object_bounds.hpp"

namespace eoir::universe {

const std::vector<ShapeInfo>& shapes() {
  static const std::vector<ShapeInfo> table = {
      {ShapeKind::sphere, "sphere", {"radius"}},
      {ShapeKind::oblate, "oblate", {"equatorial_radius", "polar_radius"}},
      {ShapeKind::box, "box", {"length_x", "width_y", "height_z"}},
      {ShapeKind::plate, "plate", {"length_x", "width_y"}},
      {ShapeKind::cylinder, "cylinder", {"radius", "length"}},
      {ShapeKind::cone, "cone", {"base_radius", "length"}},
      {ShapeKind::coupler, "coupler", {"base_radius", "top_radius", "length"}},
      {ShapeKind::none, "none", {}},
      {ShapeKind::composite, "composite", {}},  // parts in the object's `composite` property (universe/composite.hpp)
      {ShapeKind::mesh, "mesh", {"scale"}},    // metres per unit of the file named by `mesh_file`
      // Rocket plume (spec 4.3.6): a sphere of `radius` and its tangent cone,
      // `length` from the sphere's far pole to the cone's apex.
      {ShapeKind::plume, "plume", {"radius", "length"}},
  };
  return table;
}

const ShapeInfo& shape_info(ShapeKind kind) { return shapes()[static_cast<std::size_t>(kind)]; }

ShapeKind parse_shape(const std::string& name, const std::string& field) {
  for (const auto& s : shapes())
    if (name == s.name) return s.kind;
  std::string list;
  for (const auto& s : shapes()) list += std::string(list.empty() ? "" : ", ") + s.name;
  throw Error(Status::unknown_name, field + ": unknown shape '" + name + "' (known: " + list + ")");
}

void check_dimensions(ShapeKind kind, const std::vector<double>& dims, const std::string& field) {
  const ShapeInfo& shape = shape_info(kind);
  if (dims.size() != shape.dimensions.size())
    throw Error(Status::out_of_range, field + ": shape '" + shape.name + "' takes " +
                                          std::to_string(shape.dimensions.size()) + " dimensions, got " +
                                          std::to_string(dims.size()));
  for (size_t i = 0; i < dims.size(); ++i)
    check_range(dims[i], Range{object_bounds::min_length_m, object_bounds::max_length_m},
                field + "[" + std::to_string(i) + "] (" + shape.dimensions[i] + ")", "m");
  if (kind == ShapeKind::plume && !(dims[1] > 2.0 * dims[0]))
    throw Error(Status::out_of_range, field + "[1] (length): a plume's length must exceed twice its radius (the "
                                              "cone's apex outside the sphere), got " +
                                          std::to_string(dims[1]) + " m for radius " + std::to_string(dims[0]) + " m");
}

std::vector<ShapePart> split_mesh(const ShapePart& part, const MeshMaterials& materials) {
  std::vector<ShapePart> out;
  if (!part.mesh) return out;
  for (std::size_t g = 0; g < part.mesh->group_materials.size(); ++g) {
    ShapePart p = part;
    p.mesh_group = static_cast<std::int32_t>(g);
    const auto it = materials.find(part.mesh->group_materials[g]);
    if (it != materials.end()) {
      if (it->second.material) p.material = it->second.material;
      if (it->second.temperature_K) p.temperature_K = it->second.temperature_K;
      if (it->second.reflectance) p.reflectance = it->second.reflectance;
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace eoir::universe
