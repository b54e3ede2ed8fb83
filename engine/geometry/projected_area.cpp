#include "geometry/projected_area.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::geometry {
namespace {
constexpr double pi = 3.14159265358979323846;

// Exact projected area of one part for a view direction in the part frame;
// negative if the shape has no closed form here.
double analytic(const ShapePart& p, const Vec3& v) {
  const auto& d = p.dimensions_m;
  const double vz2 = std::min(1.0, v.z() * v.z());
  if (p.shape == "sphere") return pi * d[0] * d[0];
  if (p.shape == "oblate") return pi * d[0] * std::sqrt(d[0] * d[0] * vz2 + d[1] * d[1] * (1.0 - vz2));
  if (p.shape == "box")
    return d[1] * d[2] * std::fabs(v.x()) + d[0] * d[2] * std::fabs(v.y()) + d[0] * d[1] * std::fabs(v.z());
  if (p.shape == "plate") return d[0] * d[1] * std::fabs(v.z());
  if (p.shape == "cylinder") return 2.0 * d[0] * d[1] * std::sqrt(1.0 - vz2) + pi * d[0] * d[0] * std::fabs(v.z());
  if (p.shape == "none") return 0.0;
  return -1.0;
}
}  // namespace

double projected_area_m2(const std::vector<ShapePart>& parts, const Tessellation& tessellation,
                         const Vec3& toward_observer_body) {
  if (parts.size() == 1) {
    const Vec3 v = parts[0].orientation.conjugate() * toward_observer_body;
    const double a = analytic(parts[0], v.normalized());
    if (a >= 0) return a;
  }
  double area = 0;
  for (const Patch& patch : tessellation.patches)
    area += std::max(0.0, patch.normal_body.dot(toward_observer_body)) * patch.area_m2;
  return area;
}

}  // namespace eoir::geometry
