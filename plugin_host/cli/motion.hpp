// Host-side motion and attitude models of the eoir CLI (as STK computes
// positions and pushes them to EOIR). Pure math: no engine calls, so the
// models are unit-tested alone (tests/cli/test_motion.cpp).
//
// Conventions
//  - Times are seconds on the host time line (iso_time.hpp).
//  - Positions in metres, velocities in m/s.
//  - Quaternions are {w, x, y, z}, unit, and rotate BODY vectors into the
//    FRAME: v_frame = q * v_body * conj(q). The columns of the matching
//    rotation matrix are the body axes expressed in the frame. This is the
//    convention of eoir_state.attitude.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace eoir::cli {

using Vec3 = std::array<double, 3>;
using Quat = std::array<double, 4>;  // w, x, y, z

struct PosVel {
  Vec3 position{};  // m
  Vec3 velocity{};  // m/s
};

// Earth's gravitational parameter (km^3/s^2), as in the scenario schema.
constexpr double kMuEarthKm3s2 = 398600.4418;

// Classical elements of a two-body (Kepler) orbit. Angles in radians.
struct KeplerElements {
  double semi_major_axis_m = 0;
  double eccentricity = 0;  // 0 <= e < 1 (elliptic only)
  double inclination = 0;
  double raan = 0;
  double arg_perigee = 0;
  double mean_anomaly_at_epoch = 0;
  double epoch_s = 0;
  double mu_m3s2 = kMuEarthKm3s2 * 1e9;
};

// Solves Kepler's equation E - e sin E = M for the eccentric anomaly, for
// 0 <= e < 1 and any M (radians). Safeguarded Newton: the iterate always stays
// inside a bracket of the root, so it converges for e up to 0.999...
double solve_kepler(double mean_anomaly, double eccentricity);
double true_to_mean_anomaly(double true_anomaly, double eccentricity);
double eccentric_to_true_anomaly(double eccentric_anomaly, double eccentricity);

// Two-body propagation in the inertial frame of the elements (J2000).
class KeplerOrbit {
 public:
  // Throws std::invalid_argument naming the bad element.
  explicit KeplerOrbit(const KeplerElements& elements);
  PosVel at(double t_s) const;
  double period_s() const;
  double mean_motion_rad_s() const { return mean_motion_; }

 private:
  KeplerElements el_;
  double mean_motion_ = 0;
  std::array<Vec3, 2> pq_{};  // perifocal unit vectors P and Q in the frame
};

// Specific orbital energy v^2/2 - mu/r (J/kg).
double orbital_energy(const PosVel& s, double mu_m3s2);

// A ballistic missile's flight from a launch point to an impact point
// (spec 4.3.6's missiles, the engine's stages riding on it), Earth-fixed:
//  - free flight: the Keplerian ellipse through both points of a spherical
//    Earth of mean radius kBallisticEarthRadius_m, symmetric about its
//    apogee; the minimum-energy ellipse (semi-major axis (R + R sin(theta/2))
//    / 2, e = cos(theta/2) / (1 + sin(theta/2)), theta the central angle), or
//    the one whose apogee is apogee_height_m above the sphere (lofted or
//    depressed: e = (r_a - R) / (r_a - R cos(theta/2)), a = r_a / (1 + e));
//  - powered flight: the first stretch of that arc retraced from rest with a
//    speed rising linearly over burn_s (Kepler time tau = s^2 / (2 burn_s)),
//    reaching the arc's speed at burnout (tau = s - burn_s / 2 after it);
//  - heights above the sphere are laid above the WGS84 ellipsoid along the
//    geocentric direction; the Earth's rotation is left out (the arc is a
//    Kepler orbit in the rotating frame: no Coriolis or centrifugal terms).
// Before the launch the missile stands at the launch point, after the impact
// at the impact point, at rest.
constexpr double kBallisticEarthRadius_m = 6371008.8;  // IUGG mean radius

class BallisticArc {
 public:
  // Latitudes and longitudes in degrees (WGS84 geodetic: the arc ends on
  // those surface points); apogee_height_m NaN: minimum energy. Throws
  // std::invalid_argument naming the bad value (launch and impact too close
  // or antipodal, burn_s not below twice the free flight, apogee below 1 km).
  BallisticArc(double launch_lat_deg, double launch_lon_deg, double impact_lat_deg, double impact_lon_deg,
               double launch_s, double burn_s, double apogee_height_m);
  PosVel at(double t_s) const;  // Earth-fixed
  double impact_s() const { return launch_s_ + burn_s_ / 2 + flight_s_; }
  double free_flight_s() const { return flight_s_; }
  double apogee_radius_m() const { return a_ * (1 + e_); }

 private:
  PosVel kepler_at(double tau_s) const;  // on the sphere, tau from the launch point
  Vec3 e1_{}, e2_{};  // launch direction, and the in-plane normal toward the impact
  double theta_ = 0, a_ = 0, e_ = 0, n_ = 0, m0_ = 0, flight_s_ = 0, launch_s_ = 0, burn_s_ = 0;
};

struct EphemerisPoint {
  double t_s = 0;
  Vec3 position{};
  Vec3 velocity{};
};

// A table of states interpolated by cubic Hermite polynomials (position and
// velocity at both ends of each interval): exact at the nodes.
class Ephemeris {
 public:
  // Points must be strictly increasing in time, at least 2. If has_velocity
  // is false the velocities are estimated by finite differences first.
  // Throws std::invalid_argument.
  Ephemeris(std::vector<EphemerisPoint> points, bool has_velocity = true);
  // Throws std::out_of_range "time T outside the ephemeris [A, B]" (ISO UTC).
  PosVel at(double t_s) const;
  double begin_s() const { return points_.front().t_s; }
  double end_s() const { return points_.back().t_s; }

 private:
  std::vector<EphemerisPoint> points_;
};

// --- vectors and attitude -------------------------------------------------
Vec3 add(const Vec3& a, const Vec3& b);
Vec3 sub(const Vec3& a, const Vec3& b);
Vec3 scale(const Vec3& a, double s);
double dot(const Vec3& a, const Vec3& b);
Vec3 cross(const Vec3& a, const Vec3& b);
double norm(const Vec3& a);
Vec3 normalize(const Vec3& a);  // throws std::domain_error for a zero vector

// Quaternion of the rotation whose matrix has columns x, y, z (an
// orthonormal right-handed body triad expressed in the frame).
Quat quat_from_axes(const Vec3& x, const Vec3& y, const Vec3& z);
Vec3 rotate(const Quat& q, const Vec3& v);  // body -> frame
Quat multiply(const Quat& a, const Quat& b);  // the rotation b, then a
Quat conjugate(const Quat& q);
// The rotation by `angle_rad` about the unit vector `axis`.
Quat axis_angle(const Vec3& axis, double angle_rad);
// The angular velocity (rad/s, frame axes) that turns q0 into q1 in dt seconds.
Vec3 angular_velocity(const Quat& q0, const Quat& q1, double dt_s);
Quat normalize(const Quat& q);              // throws std::domain_error for zero
// Body -> local north-east-down of an aircraft's heading (from north through
// east), pitch (nose up) and roll (right wing down), deg: the ZYX Euler
// angles Rz(heading) Ry(pitch) Rx(roll); body x forward, y right, z down.
Quat heading_pitch_roll(double heading_deg, double pitch_deg, double roll_deg);

// Body +Z along `boresight`; body +X along `hint` projected perpendicular to
// +Z (if hint is (nearly) parallel, the frame axis least aligned with +Z is
// used instead); +Y = Z x X.
Quat point_z_axis(const Vec3& boresight, const Vec3& hint);
// Nadir: +Z toward the centre of the frame (-position), +X along velocity.
// Body +z along the velocity (at rest: along the position, up), x toward the
// position's side: a missile flying nose first.
Quat velocity_attitude(const PosVel& state);
Quat nadir_attitude(const PosVel& s);

// Geodetic (WGS84, degrees and metres) to Earth-fixed Cartesian metres.
Vec3 geodetic_to_ecef(double lat_deg, double lon_deg, double height_m);

}  // namespace eoir::cli
