#include "time_steps.hpp"

#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "iso_time.hpp"

namespace eoir::cli {

void check_step(double dt, const std::string& field) {
  if (!(dt > 0)) throw std::invalid_argument(field + ": must be positive");
  if (!(dt >= kMinStepS))
    throw std::invalid_argument(field + ": " + nlohmann::json(dt).dump() + " s is below the 1 ms resolution of times");
}

double default_stop(std::optional<double> start, std::optional<double> stop, const Scenario& sc) {
  const double t0 = start.value_or(sc.start_s);
  return stop.value_or(start && *start > sc.stop_s ? t0 : sc.stop_s);
}

std::vector<double> step_times(double t0, double t1, double dt, std::size_t most) {
  if (t1 < t0) throw std::invalid_argument("--stop " + format_iso(t1) + " is before the start " + format_iso(t0));
  check_step(dt, "--step");
  const std::string too_many =
      "more than " + std::to_string(most) + " time steps; use a larger step (--step or the scenario's step_s)";
  if ((t1 - t0) / dt > static_cast<double>(most)) throw std::invalid_argument(too_many);
  std::vector<double> times;
  for (long long k = 0;; ++k) {
    const double t = t0 + static_cast<double>(k) * dt;
    if (t > t1 + 1e-6) break;
    times.push_back(t);
    if (times.size() > most) throw std::invalid_argument(too_many);
  }
  if (times.back() < t1 - 1e-6) times.push_back(t1);
  return times;
}

}  // namespace eoir::cli
