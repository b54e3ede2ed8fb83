// The engine tests' common scene: the Earth, and a sensor "Sensor" on a
// shapeless host "Host" at GEO radius on +x J2000 (identity attitude: the
// sensor's default boresight), at a UTC time; the caller sets the band and
// the rest.
#pragma once
#include <memory>
#include <string>

#include "engine.hpp"

namespace eoir_test {

inline std::unique_ptr<eoir::Engine> geo_host_engine(const char* iso_utc) {
  static const double identity[4] = {1, 0, 0, 0}, zero[3] = {0, 0, 0}, host[3] = {42164.2e3, 0, 0};
  auto e = std::make_unique<eoir::Engine>();
  e->set_time(eoir::EngineTime::from(eoir::utc_from_iso(iso_utc)));
  e->add_object(eoir::universe::ObjectKind::central_body, "Earth");
  e->add_object(eoir::universe::ObjectKind::satellite, "Host");
  e->set_property("Host", "shape", eoir::Value(std::string("none")));
  e->push_state("Host", e->time(), 0, host, zero, identity);
  e->add_sensor("Sensor", "Host");
  return e;
}

}  // namespace eoir_test
