// Columns along a straight path through the atmosphere's spherical shells
// (spec 4.3.1.1: "a line integral of atmospheric density along the light
// ray, through a spherical atmosphere"; air, H2O and O3 separately, and the
// aerosol), between two points or from a point to space, for sensors on the
// ground, in the air and above the atmosphere, paths that end on the
// surface and paths that graze the limb.
//
// The shells follow the Earth's figure: the path is mapped to the space in
// which the ellipsoid is a sphere of its equatorial radius (the polar axis
// stretched by a / b, a straight line stays straight), where the levels are
// spheres. There the path crosses each level at the roots of a quadratic,
// and each piece between crossings (split at the point nearest the centre)
// lies within one layer and is integrated by 4-point Gauss-Legendre in its
// length, the altitude of each node corrected back to the ellipsoid's. A
// path that stays above the top level costs one test.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "atmosphere/profile.hpp"

namespace eoir::atmosphere {

using Vec3 = Eigen::Vector3d;

// The Earth's figure in the caller's frame.
struct EarthFigure {
  Vec3 centre_m = Vec3::Zero();
  Vec3 pole = Vec3::UnitZ();  // unit
  double equatorial_radius_m = 6378137.0, polar_radius_m = 6356752.314245;
};

// One piece of a path within one layer (kept by default: the band models
// need them): its amounts and the air-weighted
// temperature and pressure (Curtis-Godson), for band models and emission.
struct PathSegment {
  std::size_t layer = 0;  // index of the layer's lower level
  double length_m = 0;
  double air_m2 = 0, h2o_m2 = 0, o3_m2 = 0, aerosol_tau_550 = 0;
  double boundary_aerosol_tau_550 = 0;  // of which the boundary layer's
  std::array<double, kMixedGases> mixed_m2{};
  double temperature_K = 0, pressure_Pa = 0;
  double mid_distance_m = 0;  // from the path's first point to the segment's middle, along the path
  double mid_altitude_m = 0;  // of the segment's middle
};

struct PathColumns {
  bool crosses = false;  // some of the path lies below the top level
  double length_m = 0;   // within the atmosphere
  double air_m2 = 0, h2o_m2 = 0, o3_m2 = 0, aerosol_tau_550 = 0;
  double boundary_aerosol_tau_550 = 0;  // of which the boundary layer's
  double lowest_altitude_m = 0;  // the path's lowest point (of the part inside)
  std::vector<PathSegment> segments;  // from the first point (the start of a refracted path) out, when asked for
};

// Adds a segment's amounts to a path's totals (and the segment to its list).
void append_segment(PathColumns& path, const PathSegment& segment);

// Between two points.
PathColumns path_between(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                         const Vec3& to_m, bool keep_segments = true);
// From a point along a unit direction to space (nothing stops it: a caller
// whose ray meets the ground ends it there with path_between).
PathColumns path_to_space(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                          const Vec3& direction, bool keep_segments = true);

// From a point inside the atmosphere along an apparent direction (the one
// the ray arrives from), following the ray's refraction in the shells
// (Snell's invariant n r sin(zenith angle) = const, n - 1 proportional to
// the air's density, 2.926e-4 at 0 C and 1013.25 hPa in the visible): the
// column a ground telescope looks through toward a star or satellite. A ray
// below the horizon passes its lowest point and climbs again, or ends on
// the ground (`ends_on_ground`). Points above the atmosphere give
// path_to_space's straight columns.
PathColumns refracted_path_to_space(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                                    const Vec3& apparent_direction, bool& ends_on_ground, bool keep_segments = true);

// The total bending of a ray leaving a point inside the atmosphere upward
// at an apparent direction, integrated through the shells (Smart's
// integral: R = integral of tan(theta) / n |dn| along the ray): the
// refraction a ray-traced atmosphere gives, which refraction.hpp's formula
// is checked against.
double ray_traced_refraction_rad(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                                 const Vec3& apparent_direction);

// The refraction toward a point at a finite distance (an aircraft, a LEO
// satellite; issue 20 item 6): the ray leaving a point inside the
// atmosphere along an apparent direction is marched through the shells
// (d(n t)/ds = grad n, in the plane of the Earth's centre) out to the
// distance range_m, straight beyond the top level. chord_rad is the angle
// between the apparent direction and the chord to where the ray got: the
// refraction of a source there (k D / 2 R_E for a low path near the ground,
// the geodetic coefficient of refraction k); bending_rad the ray's whole
// bending to space, the refraction of a source at infinity (0 with
// ends_on_ground: the ray meets the ground, where it stops).
struct ChordRefraction {
  double chord_rad = 0, bending_rad = 0;
  bool ends_on_ground = false;
};
ChordRefraction chord_refraction(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                                 const Vec3& apparent_direction, double range_m);

// The refractivity n - 1 of air of number density air_m3 (visible light).
double refractivity(double air_m3);

// A vector (a point relative to the Earth's centre, or a direction) in the
// space where the ellipsoid is a sphere of its equatorial radius: the
// polar component stretched by a / b.
Vec3 to_sphere_space(const EarthFigure& earth, const Vec3& v);

// The geodetic altitude of a point (m), as the shells see it.
double altitude_m(const EarthFigure& earth, const Vec3& point_m);

}  // namespace eoir::atmosphere
