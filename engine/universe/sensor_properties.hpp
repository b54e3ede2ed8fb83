// The sensor parameters of spec 5 and the fidelity knobs as named, typed,
// validated properties (README "Properties").
#pragma once
#include <vector>

#include "core/value.hpp"
#include "universe/sensor_parameters.hpp"

namespace eoir::universe {

const std::vector<PropertySpec<SensorParameters>>& sensor_properties();

}  // namespace eoir::universe
