// libFuzzer target: a scenario's motion block (plugin_host/cli/scenario.cpp
// parse_motion, motion.cpp, sgp4.cpp): arbitrary bytes as the "motion" of
// one satellite, evaluated from a century before the scenario's start to a
// century after. Refusals are ScenarioError; anything else escaping is a
// finding, and so is a state that is not finite.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "json_guard.hpp"
#include "scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace eoir::cli;
  nlohmann::json motion;
  try {
    motion = parse_json_checked(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const JsonInputError&) {
    return 0;
  }
  const nlohmann::json doc = {{"format", "eoir-scenario"},
                              {"version", 1},
                              {"name", "fuzz"},
                              {"start", "2010-08-25T18:00:00Z"},
                              {"stop", "2010-08-25T18:10:00Z"},
                              {"objects", {{{"name", "Sat"}, {"kind", "satellite"}, {"motion", motion}}}}};
  try {
    const Scenario sc = parse_scenario(doc, "fuzz.json");
    for (const double offset_s : {0.0, 1e-3, 60.0, 600.0, 86400.0, -86400.0, 3.15576e9, -3.15576e9}) {
      try {
        const PosVel pv = motion_state(sc.objects.at(0), sc.start_s + offset_s);
        for (int i = 0; i < 3; ++i)
          if (!std::isfinite(pv.position[i]) || !std::isfinite(pv.velocity[i])) {
            std::fprintf(stderr, "fuzz: a state that is not finite at %+g s\n", offset_s);
            std::abort();
          }
      } catch (const ScenarioError&) {
      }
    }
  } catch (const ScenarioError&) {
  }
  return 0;
}
