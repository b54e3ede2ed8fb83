#include "geometry/part_shadow.hpp"

namespace eoir::geometry {

bool parts_block_ray(const PlacedObject& object, double bounding_radius_m, const Vec3& point_m, const Vec3& u,
                     double max_range_m) {
  const Vec3 rel = object.position_m - point_m;
  const double s = rel.dot(u);
  if (s < -bounding_radius_m || s > max_range_m + bounding_radius_m) return false;
  if ((rel - s * u).squaredNorm() > bounding_radius_m * bounding_radius_m) return false;
  const Vec3 origin_body = object.body_to_frame.transpose() * (-rel);
  const Vec3 dir_body = object.body_to_frame.transpose() * u;
  for (const ShapePart& part : object.parts) {
    const Eigen::Quaterniond to_part = part.orientation.conjugate();
    double t = 0;
    Vec3 normal;
    if (intersect_shape(part.geom, to_part * (origin_body - part.offset_m), (to_part * dir_body).normalized(), 0.0,
                        max_range_m, t, normal))
      return true;
  }
  return false;
}

}  // namespace eoir::geometry
