#include "universe/object_limits.hpp"

#include <string>

#include "core/error.hpp"

namespace eoir::universe {

bool ObjectLimits::is_default() const {
  const ObjectLimits d;
  return satellites == d.satellites && vehicles == d.vehicles && sites == d.sites && missiles == d.missiles &&
         sensors == d.sensors;
}

void check_limits(const ObjectLimits& limits) {
  const auto check = [](std::size_t value, std::size_t ceiling, const char* field) {
    if (value < 1 || value > ceiling)
      throw Error(Status::out_of_range, std::string(field) + ": " + std::to_string(value) + " outside [1, " +
                                            std::to_string(ceiling) + "]");
  };
  check(limits.satellites, ceilings::satellites, "max_satellites");
  check(limits.vehicles, ceilings::vehicles, "max_vehicles");
  check(limits.sites, ceilings::sites, "max_sites");
  check(limits.missiles, ceilings::missiles, "max_missiles");
  check(limits.sensors, ceilings::sensors, "max_sensors");
}

}  // namespace eoir::universe
