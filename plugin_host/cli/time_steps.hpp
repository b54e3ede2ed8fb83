// The time steps of a run, report or access over a scenario (one rule for
// the CLI and the host library).
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scenario.hpp"

namespace eoir::cli {

// Times have a resolution of 1 ms (format_iso, access): no step is shorter.
constexpr double kMinStepS = 1e-3;
// The most time steps of a report, and of the scenario's own times that
// validate checks (so that both accept the same scenarios).
constexpr std::size_t kMaxReportSteps = 10000000;

// Throws std::invalid_argument "FIELD: must be positive" or "FIELD: X s is
// below the 1 ms resolution of times" unless dt >= kMinStepS.
void check_step(double dt, const std::string& field);

// The stop time: `stop` if given, else the scenario's stop (or `start` if
// that lies past the scenario's stop).
double default_stop(std::optional<double> start, std::optional<double> stop, const Scenario& scenario);

// t0, t0 + dt, ... up to t1, with t1 itself always last. Throws
// std::invalid_argument "--stop X is before the start Y", check_step's
// "--step: ..." or "more than N time steps; use a larger step ..." (before
// any is made).
std::vector<double> step_times(double t0, double t1, double dt, std::size_t most);

}  // namespace eoir::cli
