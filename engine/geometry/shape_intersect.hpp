// Analytic ray/shape intersection in double precision (spec 4.1.3, 4.1.5.1;
// DESIGN.md section 3). Everything here works in one part's own frame.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "geometry/mesh_geometry.hpp"

#include "universe/shapes.hpp"

namespace eoir::geometry {

using Vec3 = Eigen::Vector3d;
using universe::ShapeKind;

// A part's shape with its dimensions decoded (metres). Sphere: a = c = r.
// Frustum shapes (cylinder, cone, coupler) use r_bottom at z = -length/2 and
// r_top at z = +length/2 (cone: r_top = 0).
struct ShapeGeom {
  ShapeKind kind = ShapeKind::none;
  double a_m = 0, c_m = 0;                 // sphere / oblate: equatorial, polar radius
  double x_m = 0, y_m = 0, z_m = 0;        // box / plate full edge lengths
  double r_bottom_m = 0, r_top_m = 0, length_m = 0;  // frustum
  std::shared_ptr<const MeshGeometry> mesh;          // mesh: the model at its scale
  std::int32_t mesh_group = -1;                      // mesh: this part's material group
};

// Plume: a = c = the sphere's radius r (centre at the origin), length_m from
// the sphere's pole at z = -r to the cone's apex on +z.
struct PlumeProfile {
  double apex_z_m = 0;         // h = length - r
  double tangent_z_m = 0;      // where the cone touches the sphere: r^2 / h
  double tangent_radius_m = 0; // radius of that circle: r sqrt(1 - r^2 / h^2)
};
PlumeProfile plume_profile(const ShapeGeom& g);

// Decodes dimensions (checked as universe::check_dimensions; throws
// eoir::Error naming `field`). Composite is not a simple shape, and a mesh
// needs its model (make_part): out_of_range.
ShapeGeom shape_geom(ShapeKind kind, const std::vector<double>& dimensions_m, const std::string& field = "shape");

// Nearest hit with t_min < t < t_max of the ray origin + t * dir (dir unit,
// part frame). Only outward-facing surfaces are reported: a ray that starts
// inside a closed shape does not see its inner wall (the lead's rule: an object
// containing the observer is invisible). The plate is two-sided: its normal is
// returned facing the ray. Grazing rays give a clean miss or hit, never NaN.
// Returns false on a miss; on a hit sets t_m and the outward unit normal,
// and *facet (if given) to the mesh triangle hit (its index in the part's
// group) or -1 for an analytic shape.
bool intersect_shape(const ShapeGeom& g, const Vec3& origin_m, const Vec3& dir, double t_min, double t_max,
                     double& t_m, Vec3& normal, std::int32_t* facet = nullptr);

// intersect_shape of rays dir[0..n) from one origin against a sphere or
// spheroid (kind sphere or oblate), each with t_min 0 and its own t_max[i]:
// hit[i], and where hit, t_m[i] and normal[i], bit for bit as n calls give
// them (four rays at a time with AVX where the processor has it: the same
// correctly rounded operations in the same order).
void intersect_spheroid_rays(const ShapeGeom& g, const Vec3& origin_m, const Vec3* dir, int n, const double* t_max,
                             bool* hit, double* t_m, Vec3* normal);

// True when p lies inside the closed shape by more than a relative 1e-9 of its
// size (a point on the surface is outside). Plate and none contain nothing.
bool shape_contains(const ShapeGeom& g, const Vec3& p_m);

// Radius of a sphere about the part origin enclosing the shape (m).
double shape_bounding_radius_m(const ShapeGeom& g);

// Exact surface area (m^2); the plate counts both faces.
double shape_surface_area_m2(const ShapeGeom& g);

// Outward unit normal of the shape's surface at (or very near) p (part frame);
// the plate returns +z for z >= 0 and -z otherwise.
Vec3 shape_normal(const ShapeGeom& g, const Vec3& p_m);

}  // namespace eoir::geometry

namespace eoir::geometry {

// Area (m^2) of the zone of an ellipsoid of revolution (equatorial radius a,
// polar c) between parametric latitudes with sines u1 <= u2 (exact, closed form).
double spheroid_zone_area_m2(double a_m, double c_m, double u1, double u2);

// Face of a box nearest p: 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z.
int box_face(const ShapeGeom& g, const Vec3& p_m);
// Face of a frustum (cylinder, cone, coupler) nearest p: 0 side, 1 bottom cap
// (z = -length/2), 2 top cap (z = +length/2, absent for the cone).
int frustum_face(const ShapeGeom& g, const Vec3& p_m);

}  // namespace eoir::geometry
