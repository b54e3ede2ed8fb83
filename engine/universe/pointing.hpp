// Pointing a sensor from where it is (its parent's place): by topocentric
// azimuth and elevation, or at another object with the angular velocity that
// keeps it there during the integration (point sources then streak as the
// sky turns past the tracked target). Each gives the sensor's own attitude as
// a state to push (the position of a sensor's state is unused).
#pragma once
#include <string>

#include "core/time.hpp"
#include "universe/object.hpp"
#include "universe/universe.hpp"

namespace eoir::universe {

// Body +z toward azimuth (deg from north through east, within +-360) and
// elevation (deg above the geodetic horizon, [-90, 90]) of the local horizon
// at the sensor's geodetic position at t; body +y toward the zenith side of
// the line of sight (up in the picture; at +-90 deg, the side away from the
// azimuth). The attitude is kept in the Earth-fixed frame without angular
// velocity, so the direction stays fixed on the local horizon as the Earth
// turns. Throws out_of_range naming azimuth_deg or elevation_deg, no_state if
// the sensor's parent has no state.
PushedState azimuth_elevation_pointing(const Universe& universe, const Object& sensor, const EngineTime& t,
                                       double azimuth_deg, double elevation_deg);

// Body +z toward the target's geometric position at t; body +y toward the
// sensor's zenith when it is within frames::horizon_max_height_m of the
// ellipsoid, else toward the J2000 north pole (the frame axis least along
// the line of sight where that is the line of sight). Kept in J2000 with the
// angular velocity of that attitude at t (central differences over +-10 ms
// of both objects' motion). Throws not_allowed for the star field, the
// sensor itself, its parent or a target at the sensor's position.
PushedState target_pointing(const Universe& universe, const Object& sensor, const std::string& target,
                            const EngineTime& t);

}  // namespace eoir::universe
