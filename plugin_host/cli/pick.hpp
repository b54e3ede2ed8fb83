// `eoir pick`: eq. 9 term by term (spec 4.1.5.3; the components of spec
// 6.2.5.4) at one scene sample or sensor pixel of a rendered frame, through
// the C ABI: eoir_render, eoir_pick_get and eoir_pick_term_get (1.6).
#pragma once
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine.hpp"
#include "scenario.hpp"

namespace eoir::cli {

// A command-line value the scenario or the frame refuses (an unknown sensor,
// x or y outside the image): the command line is wrong (exit status 1).
class PickArgumentError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct PickOptions {
  std::string scenario_file;
  std::string sensor;
  bool pixel = false;     // false: scene sample (space 0); true: sensor pixel (space 1, its centre sample)
  uint32_t x = 0, y = 0;  // column, and row from the top
  double time_s = 0;      // seconds since J2000 on the host time line (iso_time.hpp)
};

// The columns of eq. 9, in eoir_pick_term order: surface, downwelling and the
// path terms in W/(cm^2 sr um), transmittance (T_out) dimensionless.
constexpr std::array<const char*, 6> kPickTermNames = {"surface",      "downwelling",  "transmittance",
                                                       "path_thermal", "path_scatter", "at_sensor"};

struct PickTerms {
  eoir_pick pick{};                                  // hit, object, geodetic, effective radiance...
  std::vector<double> wavelength_um;                 // the sensor's spectral grid
  std::array<std::vector<double>, 6> terms;          // kPickTermNames order, one value per interval
};

// Loads the scenario into the engine, moves it to opt.time_s, renders the
// sensor and reads the pick and its terms. Throws PickArgumentError for an
// unknown sensor or a sample/pixel outside the frame (naming --sensor, --x
// or --y), EngineError or ScenarioError otherwise.
PickTerms pick_terms(Engine& engine, const Scenario& scenario, const PickOptions& opt);

// Header lines "# ..." (scenario, sensor, time, sample or pixel, what it
// hits, latitude/longitude, effective radiance, units), then
// "wavelength_um,surface,...,at_sensor" and one row per interval (%.17g).
std::string pick_csv(const Scenario& scenario, const PickOptions& opt, const PickTerms& p);
// The same as JSON (schemas/pick.schema.json): the header's fields, "units"
// and "columns" {wavelength_um: [...], surface: [...], ...}.
std::string pick_json(const Scenario& scenario, const PickOptions& opt, const PickTerms& p);

}  // namespace eoir::cli
