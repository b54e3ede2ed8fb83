// Eclipses of the Sun (spec 4.1.5.3: "geometric processing culls out point
// sources that are eclipsed"; spec 6.1.2: umbra, penumbra and the sunset
// duration): the fraction of the solar disk visible from a point, behind
// spheres and spheroids (oblate or prolate ellipsoids of revolution).
//
// Model: the Sun is a uniform disk (no limb darkening), so the visible
// fraction is the unhidden fraction of its solid angle. Umbra 0, penumbra
// between 0 and 1, antumbra (annular) 1 - (occulter / Sun apparent radius)^2,
// full sunlight 1. Positions may be relative to any origin (observer-relative
// J2000 in the engine): only differences are used, in double precision.
// Accuracy of the hidden fraction (eclipse.cpp, tested): spheres O(alpha^2),
// <= 5e-6 at 1 AU; spheroids exact in which rays are blocked, with the Sun's
// image taken as a near-circle: <= 0.13 f (f = a/c - 1) where the body looks
// as large as the Sun, < 1e-5 for the Earth seen from LEO to GEO.
#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace eoir::geometry {

using Vec3 = Eigen::Vector3d;

// A central body (spheroid: equatorial radius a, polar radius c along the unit
// polar axis) or a small object (sphere: a = c). A zero radius hides nothing.
struct Occulter {
  Vec3 centre_m = Vec3::Zero();
  double equatorial_radius_m = 0.0;
  double polar_radius_m = 0.0;
  Vec3 polar_axis = Vec3::UnitZ();  // need not be normalised; unused when a = c

  static Occulter sphere(const Vec3& centre_m, double radius_m) { return {centre_m, radius_m, radius_m, Vec3::UnitZ()}; }
};

// Area of the intersection of two disks in a plane, radii r1, r2 >= 0 and
// centre separation d >= 0 (any one length unit; the result in its square).
double circle_overlap_area(double r1, double r2, double centre_separation);

// The same with the second disk placed by the signed distance from the first
// disk's centre to the second disk's nearest edge (edge_distance = d - r2,
// negative when the first centre is covered). Stays accurate when r2 >> r1;
// r2 = +infinity is the half-plane beyond a straight edge.
double circle_overlap_area_by_edge(double r1, double r2, double edge_distance);

// Fraction in [0, 1] of the Sun's disk hidden from `point_m` by one occulter
// (1 when the point is inside it by more than a relative 1e-9; a point on
// the surface sees half the sky; 0 from inside the Sun). Occulters whose
// centre is farther than the Sun's centre hide nothing.
double solar_disk_hidden_fraction(const Vec3& point_m, const Vec3& sun_centre_m, double sun_radius_m,
                                  const Occulter& occulter);

// Fraction in [0, 1] of the Sun's disk (centre sun_centre_m, radius
// sun_radius_m >= 0; 0 is a point Sun) visible from `point_m` against every
// occulter. Several occulters over the Sun are combined as
// max(0, 1 - sum of hidden fractions), after dropping any occulter whose sky
// disk lies inside another's: exact when their sky disks over the Sun are
// disjoint or nested; when two partly overlap each other in front of the Sun
// the shared part counts twice, so the result errs toward shadow (never more
// light than the truth). A point inside the Sun sees 1. Throws eoir::Error
// (out_of_range) for non-finite input or negative radii.
double solar_disk_visible_fraction(const Vec3& point_m, const Vec3& sun_centre_m, double sun_radius_m,
                                   const Occulter* occulters, std::size_t count);
double solar_disk_visible_fraction(const Vec3& point_m, const Vec3& sun_centre_m, double sun_radius_m,
                                   const std::vector<Occulter>& occulters);

}  // namespace eoir::geometry
