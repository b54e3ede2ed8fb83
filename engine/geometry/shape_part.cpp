#include "core/error.hpp"
#include "geometry/scene_geometry.hpp"

namespace eoir::geometry {

ShapePart make_part(const universe::ShapePart& p, const std::string& field) {
  if (p.kind != universe::ShapeKind::mesh) return ShapePart{shape_geom(p.kind, p.dimensions_m, field), p.offset_m, p.orientation};
  if (!p.mesh || p.mesh_group < 0 || static_cast<std::size_t>(p.mesh_group) >= p.mesh->group_materials.size())
    throw Error(Status::internal, field + ": a mesh part without its model or group");
  universe::check_dimensions(p.kind, p.dimensions_m, field);
  ShapeGeom g;
  g.kind = universe::ShapeKind::mesh;
  g.mesh = MeshGeometry::of(p.mesh, p.dimensions_m[0]);
  g.mesh_group = p.mesh_group;
  return ShapePart{g, p.offset_m, p.orientation};
}

}  // namespace eoir::geometry
