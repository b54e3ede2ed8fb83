#include "universe/object_motion.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/value.hpp"
#include "universe/central_bodies.hpp"
#include "universe/object_bounds.hpp"

namespace eoir::universe {

void push_state(Object& object, const EngineTime& epoch, int frame, const double position[3],
                const double velocity[3], const double q[4], const double angular_velocity[3]) {
  if (object.kind == ObjectKind::central_body || object.kind == ObjectKind::star_field)
    throw Error(Status::not_allowed, "state: '" + object.name + "' moves on its own ephemeris and takes no state");
  if (object.kind == ObjectKind::site)
    throw Error(Status::not_allowed, "state: site '" + object.name +
                                         "' is fixed on the Earth at its latitude_deg, longitude_deg and height_m "
                                         "properties and takes no state (point its sensors instead)");
  namespace b = object_bounds;
  const Range metres{-b::max_position_m, b::max_position_m};
  for (int i = 0; i < 3; ++i) {
    const std::string field = "position[" + std::to_string(i) + "]";
    const bool geodetic = frame == 2 || frame == 3;
    if (geodetic && i == 0) check_range(position[0], Range{-90, 90}, field + " (latitude)", "deg");
    else if (geodetic && i == 1)
      check_range(position[1], Range{-b::max_abs_longitude_deg, b::max_abs_longitude_deg}, field + " (longitude)", "deg");
    else check_range(position[i], metres, field + (geodetic ? " (height)" : ""), "m");
  }
  for (int i = 0; i < 3; ++i) require_finite(velocity[i], "velocity[" + std::to_string(i) + "]");
  const double speed = std::sqrt(velocity[0] * velocity[0] + velocity[1] * velocity[1] + velocity[2] * velocity[2]);
  if (!(speed < b::max_speed_m_s))
    throw Error(Status::out_of_range, "velocity: must be below the speed of light, |v| = " + std::to_string(speed) + " m/s");
  for (int i = 0; i < 4; ++i) require_finite(q[i], "attitude[" + std::to_string(i) + "]");
  frames::Vec3 omega = frames::Vec3::Zero();
  if (angular_velocity) {
    for (int i = 0; i < 3; ++i) {
      require_finite(angular_velocity[i], "angular_velocity[" + std::to_string(i) + "]");
      omega[i] = angular_velocity[i];
    }
    if (!(omega.norm() <= b::max_angular_rate_rad_s))
      throw Error(Status::out_of_range, "angular_velocity: at most " + std::to_string(b::max_angular_rate_rad_s) +
                                            " rad/s, got " + std::to_string(omega.norm()));
  }
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (std::fabs(norm - 1.0) > 1e-6)
    throw Error(Status::out_of_range, "attitude: quaternion must have unit norm (|q| - 1 within 1e-6), |q| = " +
                                          std::to_string(norm));
  PushedState s;
  s.valid = true;
  s.epoch = epoch;
  s.attitude = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized();
  s.velocity_m_s = frames::Vec3(velocity[0], velocity[1], velocity[2]);
  s.angular_velocity_rad_s = omega;
  switch (frame) {
    case 0:
      s.frame = StateFrame::j2000;
      s.position_m = frames::Vec3(position[0], position[1], position[2]);
      break;
    case 1:
      s.frame = StateFrame::earth_fixed;
      s.position_m = frames::Vec3(position[0], position[1], position[2]);
      break;
    case 2:
      s.frame = StateFrame::earth_fixed;
      s.position_m = frames::geodetic_to_earth_fixed(position[0], position[1], position[2]);
      break;
    case 3: {  // local north-east-down at the place -> Earth-fixed
      s.frame = StateFrame::earth_fixed;
      s.position_m = frames::geodetic_to_earth_fixed(position[0], position[1], position[2]);
      const frames::Mat3 ned = frames::ned_to_earth_fixed(position[0], position[1]);
      s.velocity_m_s = ned * s.velocity_m_s;
      s.angular_velocity_rad_s = ned * s.angular_velocity_rad_s;
      s.attitude = (Eigen::Quaterniond(ned) * s.attitude).normalized();
      break;
    }
    default: throw Error(Status::out_of_range, "frame: unknown frame " + std::to_string(frame));
  }
  object.state = s;
}

namespace {
// The pushed attitude turned at the pushed angular velocity for dt seconds
// (body -> the state's frame): exp(omega dt) q.
Eigen::Quaterniond turned(const PushedState& s, double dt) {
  const double angle = s.angular_velocity_rad_s.norm() * dt;
  if (angle == 0.0) return s.attitude;
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, s.angular_velocity_rad_s.normalized())) * s.attitude;
}
}  // namespace

Kinematics kinematics_at(const Universe& universe, const Object& object, const EngineTime& t) {
  Kinematics k{frames::Vec3::Zero(), frames::Vec3::Zero(), Eigen::Quaterniond::Identity()};
  if (object.kind == ObjectKind::central_body) {
    central_body_state_j2000(central_body_info(object.central_body), t, k.position_m, k.velocity_m_s);
    return k;
  }
  if (object.kind == ObjectKind::star_field) return k;
  if (object.kind == ObjectKind::site) {
    // Fixed on the Earth; body axes east, north, up.
    const SiteProperties& p = object.site;
    const frames::Mat3 m = frames::j2000_to_earth_fixed(t);
    const frames::Vec3 r = frames::geodetic_to_earth_fixed(p.latitude_deg, p.longitude_deg, p.height_m);
    k.position_m = m.transpose() * r;
    k.velocity_m_s = m.transpose() * frames::Vec3(0, 0, frames::earth_rotation_rad_per_s).cross(r);
    k.attitude = Eigen::Quaterniond(m.transpose() * frames::horizon_to_earth_fixed(p.latitude_deg, p.longitude_deg));
    return k;
  }
  if (object.kind == ObjectKind::sensor) {
    const Object& parent = universe.get(object.parent, "parent");
    k = kinematics_at(universe, parent, t);
    if (object.state.valid) {
      const PushedState& s = object.state;
      const Eigen::Quaterniond q = turned(s, t.seconds_since(s.epoch));
      k.attitude = s.frame == StateFrame::j2000 ? q : Eigen::Quaterniond(frames::j2000_to_earth_fixed(t).transpose()) * q;
    }
    return k;
  }
  const PushedState& s = object.state;
  if (!s.valid) throw Error(Status::no_state, "state: object '" + object.name + "' has no state; push one first");
  const double dt = t.seconds_since(s.epoch);
  const frames::Vec3 r = s.position_m + s.velocity_m_s * dt;  // constant-velocity extrapolation
  const Eigen::Quaterniond q = turned(s, dt);
  if (s.frame == StateFrame::j2000) {
    k.position_m = r;
    k.velocity_m_s = s.velocity_m_s;
    k.attitude = q;
  } else {
    frames::earth_fixed_to_j2000(t, r, s.velocity_m_s, k.position_m, k.velocity_m_s);
    k.attitude = Eigen::Quaterniond(frames::j2000_to_earth_fixed(t).transpose()) * q;
  }
  return k;
}

}  // namespace eoir::universe
