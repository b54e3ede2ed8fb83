// Physical bounds of what an object is and where it is: each keeps every
// derived quantity (areas, solid angles, Planck radiances, ranges squared)
// finite in double through the whole model. The property tables
// (object_properties.cpp), composite parts, pushed states and
// schemas/object_properties.schema.json use them.
#pragma once

namespace eoir::universe::object_bounds {
// Temperatures: Planck's law stays finite to 1e6 K over 0.28-28 um (spec
// 4.1.1), the Rayleigh-Jeans regime (tests/scene Stability).
constexpr double max_temperature_K = 1.0e6;
// Lengths (dimensions, patch edges, part offsets): 1 um, the scale below
// which the geometric optics of spec 4.1.5 fails anyway (the band reaches
// 28 um), to 1e12 m, beyond the Sun's radius (7e8 m); areas and solid angles
// of 1 um at the largest range stay normal doubles.
constexpr double min_length_m = 1.0e-6;
constexpr double max_length_m = 1.0e12;
// Pushed positions (geocentric, or geodetic height): within 1e14 m (670 au,
// beyond the planets); velocities below the speed of light.
constexpr double max_position_m = 1.0e14;
constexpr double max_speed_m_s = 299792458.0;
// Geodetic longitudes of pushed states and sites, deg.
constexpr double max_abs_longitude_deg = 360.0;
// Heights of sites above the WGS84 ellipsoid: the deepest ocean floor
// (-11 km) to the edge of space (100 km).
constexpr double min_site_height_m = -1.1e4;
constexpr double max_site_height_m = 1.0e5;
// Pushed angular velocities, rad/s (a turn in 6 ms).
constexpr double max_angular_rate_rad_s = 1.0e3;
}  // namespace eoir::universe::object_bounds
