// libFuzzer target: eoir_sensor_load on arbitrary bytes (a sensor file).
#include <cstdint>
#include <cstring>

#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static eoir_engine engine = [] {
    eoir_engine_desc d;
    std::memset(&d, 0, sizeof d);
    d.struct_size = sizeof d;
    d.threads = 1;
    d.seed = 1;
    eoir_engine e = nullptr;
    if (eoir_engine_create(&d, &e) != EOIR_OK || eoir_object_add(e, EOIR_KIND_SATELLITE, "Sat") != EOIR_OK ||
        eoir_sensor_add(e, "Cam", "Sat") != EOIR_OK)
      std::abort();
    return e;
  }();
  eoir_fuzz::check_status(eoir_sensor_load(engine, "Cam", eoir_fuzz::write_input(data, size)));
  return 0;
}
