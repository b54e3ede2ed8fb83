// PLACEHOLDER (replaced by the eclipse geometry): spheres, binary.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace eoir::geometry {
struct Occulter {
  Eigen::Vector3d centre_m;
  double equatorial_radius_m;
  double polar_radius_m;
  Eigen::Vector3d polar_axis = Eigen::Vector3d::UnitZ();
};
inline double solar_disk_visible_fraction(const Eigen::Vector3d& p, const Eigen::Vector3d& sun, double,
                                          const std::vector<Occulter>& occulters) {
  const Eigen::Vector3d u = (sun - p).normalized();
  for (const Occulter& o : occulters) {
    const Eigen::Vector3d rel = o.centre_m - p;
    const double s = rel.dot(u);
    if (s <= 0) continue;
    if ((rel - s * u).norm() < o.equatorial_radius_m) return 0.0;
  }
  return 1.0;
}
}  // namespace eoir::geometry
