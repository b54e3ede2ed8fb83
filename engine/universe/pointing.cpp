#include "universe/pointing.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/value.hpp"
#include "universe/object_bounds.hpp"
#include "universe/object_motion.hpp"

namespace eoir::universe {
namespace {
using frames::Mat3;
using frames::Vec3;

// Body -> frame with body +z along `boresight` and body +y along `up` made
// perpendicular to it (x = y cross z: a right-handed triad).
Eigen::Quaterniond boresight_up(const Vec3& boresight, const Vec3& up) {
  const Vec3 z = boresight.normalized();
  Vec3 y = up - up.dot(z) * z;
  if (!(y.norm() > 1e-9 * up.norm())) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(z[i]) < std::fabs(z[k])) k = i;
    const Vec3 axis = Vec3::Unit(k);
    y = axis - axis.dot(z) * z;
  }
  y.normalize();
  Mat3 m;
  m.col(0) = y.cross(z);
  m.col(1) = y;
  m.col(2) = z;
  return Eigen::Quaterniond(m).normalized();
}

PushedState attitude_state(const EngineTime& t, StateFrame frame, const Eigen::Quaterniond& q, const Vec3& omega) {
  PushedState s;
  s.valid = true;
  s.epoch = t;
  s.frame = frame;
  s.attitude = q;
  s.angular_velocity_rad_s = omega;
  return s;
}
}  // namespace

PushedState azimuth_elevation_pointing(const Universe& universe, const Object& sensor, const EngineTime& t,
                                       double azimuth_deg, double elevation_deg) {
  check_range(azimuth_deg, Range{-object_bounds::max_abs_longitude_deg, object_bounds::max_abs_longitude_deg},
              "azimuth_deg", "deg");
  check_range(elevation_deg, Range{-90, 90}, "elevation_deg", "deg");
  const Vec3 g = frames::horizon_at(t, kinematics_at(universe, sensor, t).position_m).geodetic;
  const double a = azimuth_deg * constants::rad_per_deg, e = elevation_deg * constants::rad_per_deg;
  const Vec3 z = frames::direction_enu(azimuth_deg, elevation_deg);
  const Vec3 y(-std::sin(e) * std::sin(a), -std::sin(e) * std::cos(a), std::cos(e));  // d z / d elevation
  Mat3 body_to_enu;
  body_to_enu.col(0) = y.cross(z);
  body_to_enu.col(1) = y;
  body_to_enu.col(2) = z;
  const Mat3 body_to_earth_fixed = frames::horizon_to_earth_fixed(g.x(), g.y()) * body_to_enu;
  return attitude_state(t, StateFrame::earth_fixed, Eigen::Quaterniond(body_to_earth_fixed).normalized(),
                        Vec3::Zero());
}

PushedState target_pointing(const Universe& universe, const Object& sensor, const std::string& target_name,
                            const EngineTime& t) {
  const Object& target = universe.get(target_name, "target");
  if (target.kind == ObjectKind::star_field)
    throw Error(Status::not_allowed, "target: the star field has no position to point at");
  if (target.name == sensor.name || target.name == sensor.parent)
    throw Error(Status::not_allowed,
                "target: '" + target.name + "' is the sensor or its parent, which it cannot point at");
  // The attitude at t + dt from both objects' motion.
  const auto attitude_at = [&](double dt) {
    const EngineTime at = t.plus_seconds(dt);
    const Vec3 self = kinematics_at(universe, sensor, at).position_m;
    const Vec3 line = kinematics_at(universe, target, at).position_m - self;
    if (!(line.norm() > 0))
      throw Error(Status::not_allowed, "target: '" + target.name + "' is at the sensor's position");
    const frames::Horizon h = frames::horizon_at(at, self);
    const Vec3 up = h.near_earth ? Vec3(h.j2000_to_enu.row(2).transpose()) : Vec3::UnitZ();
    return boresight_up(line, up);
  };
  constexpr double h = 0.01;  // s
  const Eigen::Quaterniond q = attitude_at(0.0);
  Eigen::Quaterniond d = attitude_at(h) * attitude_at(-h).conjugate();  // turns frame vectors over 2h
  if (d.w() < 0) d.coeffs() = -d.coeffs();
  const Eigen::AngleAxisd turn(d.normalized());
  const Vec3 omega = turn.angle() > 0 ? Vec3(turn.axis() * (turn.angle() / (2 * h))) : Vec3::Zero();
  return attitude_state(t, StateFrame::j2000, q, omega);
}

}  // namespace eoir::universe
