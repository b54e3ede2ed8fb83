// The time steps of a run, report or access over a scenario (one rule for
// the CLI and the host library).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "scenario.hpp"

namespace eoir::cli {

// The stop time: `stop` if given, else the scenario's stop (or `start` if
// that lies past the scenario's stop).
double default_stop(std::optional<double> start, std::optional<double> stop, const Scenario& scenario);

// t0, t0 + dt, ... up to t1, with t1 itself always last. Throws
// std::invalid_argument "--stop X is before the start Y" or "more than N
// time steps; use a larger --step".
std::vector<double> step_times(double t0, double t1, double dt, std::size_t most);

}  // namespace eoir::cli
