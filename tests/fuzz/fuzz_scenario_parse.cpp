// libFuzzer target: the CLI's scenario reader (plugin_host/cli: the JSON
// guard, the schema checks with paths, the motion models at the start time).
// Refusals are the documented exceptions; anything else escapes and is a
// finding (libFuzzer reports the uncaught exception).
#include <cstdint>
#include <stdexcept>
#include <string>

#include "json_guard.hpp"
#include "scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace eoir::cli;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Scenario sc = parse_scenario(parse_json_checked(text), "fuzz.json");
    for (const ObjectSpec& o : sc.objects) {
      try {
        (void)motion_state(o, sc.start_s);
        (void)motion_state(o, sc.stop_s);
      } catch (const ScenarioError&) {
      }
    }
  } catch (const JsonInputError&) {
  } catch (const ScenarioError&) {
  }
  return 0;
}
