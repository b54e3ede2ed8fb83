// Save and restore (spec 3.4): the whole engine, or one sensor.
#include "capi_internal.hpp"
#include "state/scd.hpp"

using namespace eoir;
using eoir::capi::guarded;
using eoir::capi::need;
using eoir::capi::str;

extern "C" {

EOIR_API eoir_status eoir_state_save(eoir_engine engine, const char* path) {
  return capi::with_engine(engine, [&](Engine& e) { state::save_engine(e, str(path, "path")); });
}

EOIR_API eoir_status eoir_state_load(eoir_engine engine, const char* path) {
  return guarded([&] {
    need(engine, "engine");
    std::lock_guard<std::mutex> lock(engine->mutex);
    // Build the whole new engine first; swap only when it is complete, so a
    // refused file leaves the engine as it was.
    EngineOptions options = engine->engine->options();
    std::unique_ptr<Engine> loaded = state::load_engine(str(path, "path"), options);
    engine->engine = std::move(loaded);
  });
}

EOIR_API eoir_status eoir_sensor_save(eoir_engine engine, const char* sensor, const char* path) {
  return capi::with_engine(engine, [&](Engine& e) {
    state::save_sensor(e.universe().sensor(str(sensor, "sensor")), str(path, "path"));
  });
}

EOIR_API eoir_status eoir_sensor_load(eoir_engine engine, const char* sensor, const char* path) {
  return capi::with_engine(engine, [&](Engine& e) {
    const std::string name = str(sensor, "sensor");
    e.universe().sensor(name);  // must exist
    e.set_sensor_parameters(name, state::load_sensor(str(path, "path")));
  });
}
}
