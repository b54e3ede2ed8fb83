// libFuzzer target: eoir_material_load on arbitrary bytes (a material file,
// engine/universe/material.cpp through the C ABI). A loaded material must
// travel with a saved state (scd format 2) that loads again.
#include <cstdint>

#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static eoir_engine engine = eoir_fuzz::new_engine();
  // The engine without user materials, loaded again after each one so that
  // they do not pile up in the saved states.
  static const std::string empty = [] {
    const std::string path = eoir_fuzz::input_path() + ".empty.scd";
    if (eoir_state_save(engine, path.c_str()) != EOIR_OK) std::abort();
    return path;
  }();
  const eoir_status s = eoir_material_load(engine, eoir_fuzz::write_input(data, size));
  eoir_fuzz::check_status(s);
  if (s == EOIR_OK) {
    const std::string copy = eoir_fuzz::input_path() + ".scd";
    if (eoir_state_save(engine, copy.c_str()) != EOIR_OK || eoir_state_load(engine, copy.c_str()) != EOIR_OK) {
      std::fprintf(stderr, "fuzz: a state holding a loaded material does not save and load: %s\n", eoir_last_error());
      std::abort();
    }
    if (eoir_state_load(engine, empty.c_str()) != EOIR_OK) std::abort();
  }
  return 0;
}
