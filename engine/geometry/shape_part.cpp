#include "geometry/scene_geometry.hpp"

namespace eoir::geometry {

ShapePart make_part(const universe::ShapePart& p, const std::string& field) {
  return ShapePart{shape_geom(p.kind, p.dimensions_m, field), p.offset_m, p.orientation};
}

}  // namespace eoir::geometry
