// Every data-provider group of the report-generator interface, in report
// order: the static groups (static_providers) and the target group.
#pragma once
#include "metrics/static_providers.hpp"
#include "metrics/target_metrics.hpp"

namespace eoir::metrics {

constexpr const char* target_group_name = "EOIR Sensor-to-Target Metrics";

const std::vector<GroupSpec>& provider_groups();
// Throws eoir::Error(unknown_name) for an unknown group.
const GroupSpec& provider_group(const std::string& group);
// One element of the target group (Table 2 names). Throws unknown_name.
ElementValue target_element(const TargetMetrics& t, const std::string& element);

}  // namespace eoir::metrics
