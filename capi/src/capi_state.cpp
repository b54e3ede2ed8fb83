// Save and restore (spec 3.4): the whole engine, or one sensor.
#include "capi_internal.hpp"
#include "state/scd.hpp"

using namespace eoir;
using eoir::capi::guarded;
using eoir::capi::str;

extern "C" {

EOIR_API eoir_status eoir_state_save(eoir_engine engine, const char* path) {
  return guarded([&] { state::save_engine(capi::engine_of(engine), str(path, "path")); });
}

EOIR_API eoir_status eoir_state_load(eoir_engine engine, const char* path) {
  return guarded([&] {
    Engine& e = capi::engine_of(engine);
    // Build the whole new engine first; swap only when it is complete, so a
    // refused file leaves the engine as it was.
    std::unique_ptr<Engine> loaded = state::load_engine(str(path, "path"), e.options().threads);
    engine->engine = std::move(loaded);
  });
}

EOIR_API eoir_status eoir_sensor_save(eoir_engine engine, const char* sensor, const char* path) {
  return guarded([&] {
    Engine& e = capi::engine_of(engine);
    state::save_sensor(e.universe().sensor(str(sensor, "sensor")), str(path, "path"));
  });
}

EOIR_API eoir_status eoir_sensor_load(eoir_engine engine, const char* sensor, const char* path) {
  return guarded([&] {
    Engine& e = capi::engine_of(engine);
    const std::string name = str(sensor, "sensor");
    e.universe().sensor(name);  // must exist
    const sensor::SensorParameters p = state::load_sensor(str(path, "path"));
    universe::Object& o = e.universe().get(name);
    o.sensor = p;
    ++o.revision;
    e.note_change();
  });
}
}
