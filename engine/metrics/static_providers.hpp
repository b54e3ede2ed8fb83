// The static data-provider groups of the sensor (spec 5.12, Table 1; the
// report styles of spec 7.6 step 5): names, types and units, and the lookup of
// one element's value in a StaticMetrics.
#pragma once
#include <string>
#include <vector>

#include "sensor/static_metrics.hpp"

namespace eoir::metrics {
enum class ElementType { number, integer, boolean, curve };
struct ElementSpec { const char* name; ElementType type; const char* unit; const char* x_unit; };
struct GroupSpec { const char* name; bool needs_target; std::vector<ElementSpec> elements; };
// The static groups in report order.
const std::vector<GroupSpec>& static_provider_groups();
struct ElementValue { ElementType type; double number = 0; const sensor::Curve* curve = nullptr; };
// Throws eoir::Error(Status::unknown_name, "element: unknown element 'X' of group 'G'") etc.
ElementValue static_element(const sensor::StaticMetrics& m, const std::string& group, const std::string& element);
}
