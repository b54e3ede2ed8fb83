// The sensor parameters of spec 5 as named, typed, validated properties.
#pragma once
#include <vector>

#include "core/value.hpp"
#include "sensor/sensor_parameters.hpp"

namespace eoir::sensor {

const std::vector<PropertySpec<SensorParameters>>& sensor_properties();
// Cross-field checks (band edges in order, ...) that single setters cannot
// make; throws eoir::Error(out_of_range) naming the fields.
void check_consistency(const SensorParameters& p);

}  // namespace eoir::sensor
