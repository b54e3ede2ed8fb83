// The atmosphere between a sensor and a target (spec 4.3.1.1, 6.2.5.4): the
// air mass it looks through (in vertical sea-level columns: straight up from
// the ground is 1, 6.2.5.4), the water-vapour and ozone columns, the
// aerosol's and the air's optical depths at 0.55 um, the length inside the
// atmosphere, and the topocentric elevation of the target. A sensor inside
// the atmosphere looking at a target above it follows the refracted ray;
// other paths are straight. Zero while the Earth's atmosphere is off.
// Reported with the sensor-to-target metrics.
#pragma once
#include <string>

#include "metrics/static_providers.hpp"
#include "scene/world.hpp"

namespace eoir::metrics {

struct AtmosphericPathMetrics {
  bool atmosphere = false;      // the Earth's atmosphere is on
  double air_mass = 0;          // air column / the sea-level vertical column
  double h2o_g_cm2 = 0;         // precipitable water along the path
  double o3_atm_cm = 0;
  double aerosol_optical_depth_550 = 0;
  double rayleigh_optical_depth_550 = 0;
  double length_in_atmosphere_km = 0;
  double elevation_deg = 0;     // of the target above the sensor's geodetic horizon (no refraction)
  double apparent_elevation_deg = 0;  // raised by the refraction (sensors inside the atmosphere; WorldObject::seen)
  double sensor_altitude_km = 0, target_altitude_km = 0;
};

AtmosphericPathMetrics atmospheric_path(const scene::World& world, const scene::WorldObject& target);

// Its elements, reported with the sensor-to-target metrics (appended to
// the group "EOIR Sensor-to-Target Metrics", which hosts already know needs
// a target).
const std::vector<ElementSpec>& atmospheric_path_elements();
bool is_atmospheric_path_element(const std::string& element);
// Throws unknown_name naming the element.
ElementValue atmospheric_path_element(const AtmosphericPathMetrics& m, const std::string& element);

}  // namespace eoir::metrics
