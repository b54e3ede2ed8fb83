#include "geometry/projected_area.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::geometry {
namespace {
constexpr double pi = 3.14159265358979323846;

// Exact projected area of one part for a view direction in the part frame;
// negative if the shape has no closed form here.
double analytic(const ShapePart& p, const Vec3& v) {
  const ShapeGeom& g = p.geom;
  const double vz2 = std::min(1.0, v.z() * v.z());
  switch (g.kind) {
    case ShapeKind::sphere: return pi * g.a_m * g.a_m;
    case ShapeKind::oblate: return pi * g.a_m * std::sqrt(g.a_m * g.a_m * vz2 + g.c_m * g.c_m * (1.0 - vz2));
    case ShapeKind::box:
      return g.y_m * g.z_m * std::fabs(v.x()) + g.x_m * g.z_m * std::fabs(v.y()) + g.x_m * g.y_m * std::fabs(v.z());
    case ShapeKind::plate: return g.x_m * g.y_m * std::fabs(v.z());
    case ShapeKind::cylinder:
      return 2.0 * g.r_bottom_m * g.length_m * std::sqrt(1.0 - vz2) + pi * g.r_bottom_m * g.r_bottom_m * std::fabs(v.z());
    case ShapeKind::none: return 0.0;
    default: return -1.0;
  }
}
}  // namespace

double analytic_projected_area_m2(const ShapePart& part, const Vec3& toward_observer_body) {
  const Vec3 v = part.orientation.conjugate() * toward_observer_body;
  return analytic(part, v.normalized());
}

double projected_area_m2(const std::vector<ShapePart>& parts, const Tessellation& tessellation,
                         const Vec3& toward_observer_body) {
  if (parts.size() == 1) {
    const double a = analytic_projected_area_m2(parts[0], toward_observer_body);
    if (a >= 0) return a;
  }
  double area = 0;
  for (const Patch& patch : tessellation.patches)
    area += std::max(0.0, patch.normal_body.dot(toward_observer_body)) * patch.area_m2;
  return area;
}

}  // namespace eoir::geometry
