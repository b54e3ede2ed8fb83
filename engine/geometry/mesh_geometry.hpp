// A mesh model (universe/mesh_model.hpp) at one scale, ready for rays: its
// vertices in metres of the part frame, each material group's triangles in an
// Embree triangle hierarchy built once per model and scale (shared by every
// object, part and frame that uses it), and the exact double-precision
// answers the analytic shapes give (shape_intersect.hpp): the nearest hit,
// containment, the nearest triangle of a point, areas and volume.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "universe/mesh_model.hpp"

namespace eoir::geometry {

class MeshGeometry {
 public:
  using Vec3 = Eigen::Vector3d;
  // The geometry of `model` scaled by `scale` (metres per file unit), built
  // on first use and kept while the model lives.
  static std::shared_ptr<const MeshGeometry> of(const std::shared_ptr<const universe::MeshModel>& model, double scale);
  ~MeshGeometry();
  MeshGeometry(const MeshGeometry&) = delete;
  MeshGeometry& operator=(const MeshGeometry&) = delete;

  std::int32_t groups() const;
  // Triangles of a group, by their index in the model.
  const std::vector<std::int32_t>& group_triangles(std::int32_t group) const;
  // Nearest hit of origin + t dir with t_min < t < t_max on a group (part
  // frame, dir unit): t in double on the triangle's plane, its unit normal
  // (outward on a closed piece, toward the ray on an open sheet) and the
  // triangle's index in the group (group_triangles).
  bool intersect(std::int32_t group, const Vec3& origin_m, const Vec3& dir, double t_min, double t_max, double& t_m,
                 Vec3& normal, std::int32_t& facet) const;
  // The same for up to 16 rays from one origin at once (a coherent packet:
  // Embree traverses them together): rays k < count with active[k] and a
  // hit closer than t_max[k] get t_max[k], normal[k] and facet[k] replaced;
  // returns how many did.
  int intersect16(std::int32_t group, const Vec3& origin_m, const Vec3* dirs, const bool* active, int count,
                  double t_min, double* t_max, Vec3* normal, std::int32_t* facet) const;
  // True when p lies inside a closed piece of the whole model, deeper than a
  // relative 1e-9 of its size.
  bool contains(const Vec3& p_m) const;
  // The triangle of the group nearest p (model index).
  std::int32_t nearest_triangle(std::int32_t group, const Vec3& p_m) const;
  // Radius about the part origin enclosing the group.
  double bounding_radius_m(std::int32_t group) const;
  // Surface of the group, open sheets counted on both faces.
  double surface_area_m2(std::int32_t group) const;
  // The group's share of the enclosed volume (sums to the closed pieces' volume).
  double volume_m3(std::int32_t group) const;

  // Per triangle (model index): its centroid, unit normal (outward where
  // closed, the file's winding on open sheets), area, and whether it is
  // one-sided (closed).
  const Vec3& centroid_m(std::int32_t triangle) const;
  const Vec3& normal(std::int32_t triangle) const;
  double area_m2(std::int32_t triangle) const;
  bool one_sided(std::int32_t triangle) const;

 private:
  MeshGeometry();
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace eoir::geometry
