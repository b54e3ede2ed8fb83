// Where an object is at the engine time: pushed states moved along their
// velocity and turned at their angular velocity, central bodies from their
// ephemerides, sites fixed on the Earth, sensors on their parents.
#pragma once
#include <Eigen/Geometry>

#include "core/frames.hpp"
#include "universe/universe.hpp"

namespace eoir::universe {

struct Kinematics {
  frames::Vec3 position_m;    // geocentric J2000
  frames::Vec3 velocity_m_s;  // J2000
  Eigen::Quaterniond attitude;  // body -> J2000
};

// Throws eoir::Error(no_state) if the object (or a sensor's parent) has no
// pushed state. A site's attitude is its local horizon (x east, y north, z up).
Kinematics kinematics_at(const Universe& universe, const Object& object, const EngineTime& t);

// Validates and stores a state pushed by the host. frame: 0 J2000, 1
// Earth-fixed, 2 geodetic (position = lat deg, lon deg, height m), 3
// geodetic with velocity, attitude and angular velocity in the local
// north-east-down axes there (kept as an Earth-fixed state, as 2 is); the
// angular velocity (NULL = none) is about the frame's axes. Positions,
// speeds and rates within object_bounds. Throws eoir::Error naming the field (position[1],
// attitude, angular_velocity[2], frame, ...); central bodies, the star field
// and sites take no state (not_allowed).
void push_state(Object& object, const EngineTime& epoch, int frame, const double position[3],
                const double velocity[3], const double attitude_wxyz[4],
                const double angular_velocity_rad_s[3] = nullptr);

}  // namespace eoir::universe
