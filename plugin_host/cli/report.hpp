// Data-provider reports: evaluate a group's elements at a time and write the
// rows as JSON (schemas/report.schema.json), CSV or a readable table.
#pragma once
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "engine.hpp"

namespace eoir::cli {

struct ElementInfo {
  std::string name;
  int32_t type = EOIR_TYPE_NUMBER;  // NUMBER, INTEGER, BOOL or CURVE
  std::string unit, x_unit;
};

struct ElementValue {
  const ElementInfo* info = nullptr;
  double value = 0;           // scalars (bool as 0/1)
  std::vector<double> x, y;   // curves
};

struct ReportRow {
  double t_s = 0;
  std::vector<ElementValue> values;
};

// Every group name the engine provides, in its order.
std::vector<std::string> provider_groups(const eoir_api_v1& api);
// The elements of a group (empty if the group is unknown).
std::vector<ElementInfo> provider_elements(const eoir_api_v1& api, const std::string& group);

// Evaluates every element at the engine's current time. Throws EngineError
// ("GROUP / ELEMENT: engine message").
ReportRow evaluate_row(const Engine& engine, const std::string& group, const std::vector<ElementInfo>& elements,
                       const std::string& sensor, const std::optional<std::string>& target, double t_s);

// {"provider", "sensor", "target", "rows": [{"time", "values": {ELEMENT:
// {"value", "unit"[, "x", "x_unit"]}}}]}: curves give "value" = y values and
// "x" = spatial frequencies; integers as JSON integers, bools as true/false.
void write_json(std::ostream& out, const std::string& provider, const std::string& sensor,
                const std::optional<std::string>& target, const std::vector<ReportRow>& rows);
// Header "time,ELEMENT [unit],..." then one line per row (%.17g). Curve
// elements are omitted (returns true if any was).
bool write_csv(std::ostream& out, const std::vector<ElementInfo>& elements, const std::vector<ReportRow>& rows);
// "Element  value  unit" lines under a group heading (%.6g; curves as
// "curve, N points").
void write_table(std::ostream& out, const std::string& group, const ReportRow& row);

}  // namespace eoir::cli
