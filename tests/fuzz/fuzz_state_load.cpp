// libFuzzer target: eoir_state_load on arbitrary bytes (engine/state/scd.cpp
// through the C ABI). Loaded states must also save and load again.
#include <cstdint>

#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static eoir_engine engine = eoir_fuzz::new_engine();
  const eoir_status s = eoir_state_load(engine, eoir_fuzz::write_input(data, size));
  eoir_fuzz::check_status(s);
  if (s == EOIR_OK) {
    const std::string copy = eoir_fuzz::input_path() + ".scd";
    if (eoir_state_save(engine, copy.c_str()) != EOIR_OK || eoir_state_load(engine, copy.c_str()) != EOIR_OK) {
      std::fprintf(stderr, "fuzz: a loaded state does not save and load again: %s\n", eoir_last_error());
      std::abort();
    }
  }
  return 0;
}
