#include "universe/universe.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "core/utf8.hpp"
#include "universe/central_bodies.hpp"
#include "universe/spectrum_table.hpp"

namespace eoir::universe {
namespace {
void check_limit(std::size_t have, std::size_t limit, const char* what, const char* field) {
  if (have >= limit)
    throw Error(Status::limit_exceeded, std::string("kind: at most ") + std::to_string(limit) + " " + what +
                                            " (the engine's " + field +
                                            "; spec 3.1's by default): remove one first, or raise " + field +
                                            " (eoir_engine_set_limits)");
}

// Names travel into files (.scd, FITS, JSON): valid UTF-8 without control
// characters.
void check_name_text(const std::string& name) {
  const std::string problem = printable_utf8_problem(name);
  if (!problem.empty()) throw Error(Status::out_of_range, "name: " + problem);
}
}  // namespace

Universe::Universe() { add(ObjectKind::central_body, "Sun"); }

Object& Universe::add(ObjectKind kind, const std::string& name, const std::string& parent) {
  if (name.empty()) throw Error(Status::out_of_range, "name: must not be empty");
  if (name.size() > limits::max_name_length)
    throw Error(Status::out_of_range, "name: longer than " + std::to_string(limits::max_name_length) + " bytes");
  check_name_text(name);
  if (find(name)) throw Error(Status::already_exists, "name: an object named '" + name + "' already exists");
  Object o;
  o.name = name;
  o.kind = kind;
  switch (kind) {
    case ObjectKind::central_body: {
      const CentralBodyInfo* body = find_central_body(name);
      if (!body)
        throw Error(Status::unknown_name, "name: '" + name +
                                              "' is not a central body (Sun, Mercury, Venus, Earth, Mars, Jupiter, "
                                              "Saturn, Uranus, Neptune, Moon)");
      o.central_body = body->id;
      if (body->id == CentralBody::sun) o.body.spectrum = sun_spectrum;  // its measured radiance (spec 4.1.4)
      const CentralBodySurface& surface = central_body_surface(body->id);
      o.body.material = surface.material;
      o.body.reflectance = surface.reflectance;
      o.body.temperature_K = surface.temperature_K;
      if (surface.night_temperature_K > 0) {
        o.body.thermal_model = ThermalModel::subsolar;
        o.body.subsolar_temperature_K = surface.temperature_K;
        o.body.night_temperature_K = surface.night_temperature_K;
      }
      if (surface.climatology) o.body.thermal_model = ThermalModel::climatology;
      o.body.shape = ShapeKind::oblate;
      o.body.dimensions_m = {body->equatorial_radius_m, body->polar_radius_m};
      o.body.rings = body->id == CentralBody::saturn;  // observed magnitudes include them
      break;
    }
    case ObjectKind::star_field:
      if (name != "Stars") throw Error(Status::unknown_name, "name: the star field must be named 'Stars'");
      break;
    case ObjectKind::satellite: check_limit(count(kind), limits_.satellites, "satellites", "max_satellites"); break;
    case ObjectKind::aircraft:
    case ObjectKind::ground_vehicle:
      check_limit(count(ObjectKind::aircraft) + count(ObjectKind::ground_vehicle), limits_.vehicles,
                  "aircraft plus ground vehicles", "max_vehicles");
      break;
    case ObjectKind::missile: check_limit(count(kind), limits_.missiles, "missiles", "max_missiles"); break;
    case ObjectKind::site:
      check_limit(count(kind), limits_.sites, "sites", "max_sites");
      o.body.shape = ShapeKind::none;  // images nothing
      o.body.dimensions_m.clear();
      break;
    case ObjectKind::sensor: {
      check_limit(count(kind), limits_.sensors, "sensors (scene-generator/sensor-model pairs)", "max_sensors");
      const Object& p = get(parent, "parent");
      if (p.kind == ObjectKind::star_field || p.kind == ObjectKind::sensor)
        throw Error(Status::not_allowed,
                    "parent: a sensor cannot be attached to " + std::string(kind_name(p.kind)) + " '" + parent + "'");
      o.parent = parent;
      break;
    }
    default: throw Error(Status::out_of_range, "kind: unknown object kind " + std::to_string(static_cast<int>(kind)));
  }
  index_.emplace(o.name, objects_.size());
  ++counts_[static_cast<std::size_t>(o.kind)];
  objects_.push_back(std::move(o));
  return objects_.back();
}

void Universe::reindex() {
  index_.clear();
  counts_.fill(0);
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    index_.emplace(objects_[i].name, i);
    ++counts_[static_cast<std::size_t>(objects_[i].kind)];
  }
}

void Universe::set_limits(const ObjectLimits& limits) {
  check_limits(limits);
  const auto check = [](std::size_t limit, std::size_t have, const char* field, const char* what) {
    if (limit < have)
      throw Error(Status::not_allowed, std::string(field) + ": " + std::to_string(limit) + " is below the " +
                                           std::to_string(have) + " " + what + " the engine holds; remove some first");
  };
  check(limits.satellites, count(ObjectKind::satellite), "max_satellites", "satellites");
  check(limits.vehicles, count(ObjectKind::aircraft) + count(ObjectKind::ground_vehicle), "max_vehicles",
        "aircraft plus ground vehicles");
  check(limits.sites, count(ObjectKind::site), "max_sites", "sites");
  check(limits.missiles, count(ObjectKind::missile), "max_missiles", "missiles");
  check(limits.sensors, count(ObjectKind::sensor), "max_sensors", "sensors");
  limits_ = limits;
}

void Universe::remove(const std::string& name) {
  const Object& o = get(name);
  if (o.kind == ObjectKind::central_body && o.central_body == CentralBody::sun)
    throw Error(Status::not_allowed, "name: the Sun cannot be removed (spec 3.1)");
  const std::string gone = o.name;
  objects_.erase(std::remove_if(objects_.begin(), objects_.end(),
                                [&](const Object& x) {
                                  return x.name == gone || (x.kind == ObjectKind::sensor && x.parent == gone);
                                }),
                 objects_.end());
  reindex();
}

Object* Universe::find(const std::string& name) {
  const auto it = index_.find(name);
  return it == index_.end() ? nullptr : &objects_[it->second];
}
const Object* Universe::find(const std::string& name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? nullptr : &objects_[it->second];
}
Object& Universe::get(const std::string& name, const char* field) {
  if (Object* o = find(name)) return *o;
  throw Error(Status::unknown_name, std::string(field) + ": no object named '" + name + "'");
}
const Object& Universe::get(const std::string& name, const char* field) const {
  if (const Object* o = find(name)) return *o;
  throw Error(Status::unknown_name, std::string(field) + ": no object named '" + name + "'");
}
const Object& Universe::sensor(const std::string& name, const char* field) const {
  const Object& o = get(name, field);
  if (o.kind != ObjectKind::sensor)
    throw Error(Status::unknown_name, std::string(field) + ": '" + name + "' is a " + kind_name(o.kind) +
                                          ", not a sensor");
  return o;
}

}  // namespace eoir::universe
