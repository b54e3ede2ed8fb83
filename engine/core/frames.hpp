// Reference frames: Earth-centred J2000 (GCRS) and Earth-fixed (ITRS/WGS84),
// and geodetic coordinates through GeographicLib. Earth rotation from ERFA's
// IAU 2006/2000A model with UT1 = UTC and zero polar motion (no EOP data is
// reachable at run time; the error is below 0.9 s of rotation, ~400 m at GEO).
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/time.hpp"

namespace eoir::frames {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Rotation taking J2000 (GCRS) vectors to Earth-fixed (ITRS) at time t: the
// IAU 2006/2000A CIO-based chain (eraC2t06a without polar motion, UT1 = UTC).
// The celestial-to-intermediate matrix (precession-nutation, eraC2i06a) is
// ERFA's at nodes kCelestialPoleGridStep_s apart (TT) and linear between
// them: its fastest term (0.6" at 13.66 d) bends by at most 3e-11 rad over a
// step; the Earth rotation angle is exact at t. The grid is fixed in TT, so
// results do not depend on what was asked before.
constexpr double kCelestialPoleGridStep_s = 1800.0;
Mat3 j2000_to_earth_fixed(const EngineTime& t);
// Earth's rotation rate (rad/s) about ITRS z.
constexpr double earth_rotation_rad_per_s = 7.292115146706979e-5;

void earth_fixed_to_j2000(const EngineTime& t, const Vec3& r_ef, const Vec3& v_ef, Vec3& r_j2000, Vec3& v_j2000);
void j2000_to_earth_fixed(const EngineTime& t, const Vec3& r_j2000, const Vec3& v_j2000, Vec3& r_ef, Vec3& v_ef);

// WGS84 geodetic (lat deg, lon deg, height m) <-> Earth-fixed metres.
Vec3 geodetic_to_earth_fixed(double lat_deg, double lon_deg, double height_m);
Vec3 earth_fixed_to_geodetic(const Vec3& r_ef);

// The local horizon (topocentric) frame at a geodetic latitude and longitude:
// columns east, north and up (the WGS84 ellipsoid's normal), in Earth-fixed
// axes.
Mat3 horizon_to_earth_fixed(double lat_deg, double lon_deg);
// The local north-east-down frame there (aircraft axes: x north, y east,
// z down along the ellipsoid's inward normal), columns in Earth-fixed axes.
Mat3 ned_to_earth_fixed(double lat_deg, double lon_deg);
// Topocentric azimuth (deg from north through east, [0, 360)) and elevation
// (deg above the geodetic horizon, [-90, 90]) of a direction given in the
// horizon frame's own axes (east, north, up); the azimuth is 0 straight up
// or down.
void azimuth_elevation_deg(const Vec3& direction_enu, double& azimuth_deg, double& elevation_deg);
// The unit vector (east, north, up) of a topocentric azimuth and elevation.
Vec3 direction_enu(double azimuth_deg, double elevation_deg);

// Points within this height of the WGS84 ellipsoid (ground, aircraft) have a
// local horizon: truth gives topocentric azimuth and elevation from them, and
// tracking keeps their zenith up in the picture.
constexpr double horizon_max_height_m = 1.0e5;

// The local horizon of a geocentric J2000 position at time t.
struct Horizon {
  bool near_earth = false;               // |height| <= horizon_max_height_m
  Vec3 geodetic = Vec3::Zero();          // lat deg, lon deg, height m
  Mat3 j2000_to_enu = Mat3::Identity();  // rows: east, north, up in J2000 axes
};
Horizon horizon_at(const EngineTime& t, const Vec3& position_j2000);

}  // namespace eoir::frames
