// libFuzzer target: eoir_sensor_load on arbitrary bytes (a sensor file).
#include <cstdint>

#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static eoir_engine engine = [] {
    eoir_engine e = eoir_fuzz::new_engine();
    if (eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat") != EOIR_OK || eoir_sensor_add(e, "Cam", "Sat") != EOIR_OK)
      std::abort();
    return e;
  }();
  eoir_fuzz::check_status(eoir_sensor_load(engine, "Cam", eoir_fuzz::write_input(data, size)));
  return 0;
}
