// Test host for the scene-generation validation: loads a scenario file of
// scenarios/validation/ through the CLI's own scenario code, drives the
// engine through the C ABI (loaded as a plugin, as every host does), renders
// and reads images and picks back. Tests may edit the scenario JSON first,
// as the spec's procedures change properties between runs.
#pragma once
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine.hpp"
#include "scenario.hpp"
#include "session.hpp"

namespace eoir::test {

struct Image {
  int width = 0, height = 0;
  std::vector<double> values;  // row-major, row 0 at the top
  double at(int x, int y) const { return values[static_cast<size_t>(y) * width + x]; }
  double mean(int x0, int y0, int w, int h) const;
  double stddev(int x0, int y0, int w, int h) const;
  double sum() const;
};

struct Pick {
  bool hit = false;
  std::string object;
  double range_m = 0, effective_radiance = 0, lat_deg = 0, lon_deg = 0;
};

class ScenarioHost {
 public:
  // `name` is a file in scenarios/validation/; `edit` may change the JSON.
  explicit ScenarioHost(const std::string& name, const std::function<void(nlohmann::json&)>& edit = {});
  // Time = scenario start + seconds; pushes all states.
  void at(double seconds_after_start = 0.0);
  void set_number(const std::string& object, const std::string& property, double value);
  void set_bool(const std::string& object, const std::string& property, bool value);
  void set_string(const std::string& object, const std::string& property, const std::string& value);
  void render(const std::string& sensor = "Sensor1");
  Image image(int kind, const std::string& sensor = "Sensor1");
  Pick pick(int x, int y, int space = 0, const std::string& sensor = "Sensor1");
  double metric(const std::string& group, const std::string& element, const std::string& sensor = "Sensor1");
  // An element of "EOIR Sensor-to-Target Metrics" for `target` (spec 5.13).
  double target_metric(const std::string& element, const std::string& target, const std::string& sensor = "Sensor1");
  // The engine status and message of a target-metric request (for bad input).
  eoir_status try_target_metric(const std::string& element, const std::string& target, const std::string& sensor,
                                std::string& message);
  const eoir_api_v1& api() const { return engine_->api(); }
  eoir_engine handle() const { return engine_->handle(); }

 private:
  std::unique_ptr<cli::Engine> engine_;
  std::unique_ptr<cli::Scenario> scenario_;
  std::unique_ptr<cli::Session> session_;
};

// The spec scenario file's path.
std::string validation_scenario(const std::string& name);

// Reference band radiance of a blackbody over 8-12 um, independent of the
// engine: composite Simpson over eq. 5 with 4000 intervals (error < 1e-10
// relative), W/(cm^2 sr). 0 at T = 0.
double reference_band_radiance_8_12(double temperature_K);

}  // namespace eoir::test
