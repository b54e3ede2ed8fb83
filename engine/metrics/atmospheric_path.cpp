#include "metrics/atmospheric_path.hpp"

#include <algorithm>
#include <cmath>

#include "atmosphere/rayleigh.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::metrics {
using geometry::Vec3;

AtmosphericPathMetrics atmospheric_path(const scene::World& world, const scene::WorldObject& target) {
  AtmosphericPathMetrics m;
  const scene::WorldAtmosphere& a = world.atmosphere;
  if (!a.on()) return m;
  m.atmosphere = true;
  const Vec3 observer = Vec3::Zero(), to = target.placed.position_m;
  const double range = to.norm();
  m.sensor_altitude_km = atmosphere::altitude_m(a.earth, observer) / 1e3;
  m.target_altitude_km = atmosphere::altitude_m(a.earth, to) / 1e3;
  if (range > 0) {
    const auto elevation_deg = [&](const Vec3& u) {
      return std::asin(std::clamp(a.zenith.dot(u), -1.0, 1.0)) * constants::deg_per_rad;
    };
    m.elevation_deg = elevation_deg(to / range);
    // Refracted as the image places it (WorldObject::seen).
    m.apparent_elevation_deg = elevation_deg(target.seen.position_m.normalized());
  }
  const atmosphere::PathColumns c = a.path_to(to);
  m.air_mass = a.air_mass(c);
  m.h2o_g_cm2 = atmosphere::precipitable_water_g_cm2(c.h2o_m2);
  m.o3_atm_cm = atmosphere::atm_cm(c.o3_m2);
  m.aerosol_optical_depth_550 = c.aerosol_tau_550;
  m.rayleigh_optical_depth_550 = c.air_m2 * atmosphere::rayleigh_cross_section_m2(0.55);
  m.length_in_atmosphere_km = c.length_m / 1e3;
  return m;
}

const std::vector<ElementSpec>& atmospheric_path_elements() {
  static const std::vector<ElementSpec> elements{
      {"Air Mass", ElementType::number, "", ""},
      {"Water Vapor Column", ElementType::number, "g/cm^2", ""},
      {"Ozone Column", ElementType::number, "atm-cm", ""},
      {"Aerosol Optical Depth", ElementType::number, "", ""},
      {"Rayleigh Optical Depth", ElementType::number, "", ""},
      {"Path Length in Atmosphere", ElementType::number, "km", ""},
      {"Target Elevation", ElementType::number, "deg", ""},
      {"Apparent Target Elevation", ElementType::number, "deg", ""},
      {"Sensor Altitude", ElementType::number, "km", ""},
      {"Target Altitude", ElementType::number, "km", ""},
      {"Atmosphere On", ElementType::boolean, "", ""},
  };
  return elements;
}

bool is_atmospheric_path_element(const std::string& element) {
  for (const ElementSpec& e : atmospheric_path_elements())
    if (element == e.name) return true;
  return false;
}

ElementValue atmospheric_path_element(const AtmosphericPathMetrics& m, const std::string& e) {
  auto number = [](double v) { return ElementValue{ElementType::number, v, nullptr}; };
  if (e == "Air Mass") return number(m.air_mass);
  if (e == "Water Vapor Column") return number(m.h2o_g_cm2);
  if (e == "Ozone Column") return number(m.o3_atm_cm);
  if (e == "Aerosol Optical Depth") return number(m.aerosol_optical_depth_550);
  if (e == "Rayleigh Optical Depth") return number(m.rayleigh_optical_depth_550);
  if (e == "Path Length in Atmosphere") return number(m.length_in_atmosphere_km);
  if (e == "Target Elevation") return number(m.elevation_deg);
  if (e == "Apparent Target Elevation") return number(m.apparent_elevation_deg);
  if (e == "Sensor Altitude") return number(m.sensor_altitude_km);
  if (e == "Target Altitude") return number(m.target_altitude_km);
  if (e == "Atmosphere On") return ElementValue{ElementType::boolean, m.atmosphere ? 1.0 : 0.0, nullptr};
  throw Error(Status::unknown_name, "element: unknown atmospheric path element '" + e + "'");
}

}  // namespace eoir::metrics
