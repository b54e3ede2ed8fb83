#include "state/scd.hpp"

#include <cstdint>
#include <limits>
#include <set>
#include <sstream>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "universe/sensor_properties.hpp"
#include "core/read_file.hpp"
#include "state/atomic_file.hpp"
#include "universe/json_document.hpp"
#include "universe/material.hpp"
#include "universe/object_motion.hpp"
#include "universe/object_properties.hpp"

namespace eoir::state {
namespace {
using nlohmann::json;
using universe::Object;
using universe::ObjectKind;

[[noreturn]] void corrupt(const std::string& where, const std::string& what) {
  throw Error(Status::corrupt_file, where + ": " + what);
}

// Refuses fields other than `allowed` and checks the required ones.
void check_fields(const json& j, const std::string& where, const std::set<std::string>& allowed,
                  const std::set<std::string>& required) {
  if (!j.is_object()) corrupt(where, "expected an object");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!allowed.count(it.key())) corrupt(where + "." + it.key(), "unknown field");
  for (const auto& r : required)
    if (!j.contains(r)) corrupt(where + "." + r, "missing");
}

// An integral field must be a JSON integer within T's range (nlohmann would
// convert a float such as 1e112 by a cast that is undefined out of range).
template <class T>
T integer_value(const json& v, const std::string& field) {
  using limits = std::numeric_limits<T>;
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u <= static_cast<std::uint64_t>(limits::max())) return static_cast<T>(u);
  } else if (v.is_number_integer()) {
    const auto i = v.get<std::int64_t>();
    if (limits::is_signed ? i >= static_cast<std::int64_t>(limits::min()) && i <= static_cast<std::int64_t>(limits::max())
                          : i >= 0)
      return static_cast<T>(i);
  } else {
    corrupt(field, "expected an integer");
  }
  corrupt(field, "integer out of range [" + std::to_string(limits::min()) + ", " + std::to_string(limits::max()) + "]");
}

template <class T>
T field(const json& j, const std::string& key, const std::string& where) {
  try {
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>)
      return integer_value<T>(j.at(key), where + "." + key);
    else
      return j.at(key).get<T>();
  } catch (const json::exception&) {
    corrupt(where + "." + key, "missing or of the wrong type");
  }
}

template <class T>
T optional_field(const json& j, const std::string& key, const T& absent, const std::string& where) {
  return j.contains(key) ? field<T>(j, key, where) : absent;
}

void check_format(const json& doc, const char* format, int version, const std::string& where) {
  const auto f = field<std::string>(doc, "format", where);
  if (f != format) corrupt(where + ".format", "expected '" + std::string(format) + "', got '" + f + "'");
  const auto v = field<int>(doc, "version", where);
  if (v > version)
    throw Error(Status::file_version, where + ".version: file format version " + std::to_string(v) +
                                          " is newer than this engine reads (" + std::to_string(version) + ")");
  if (v < 1) corrupt(where + ".version", "must be >= 1");
}

json value_to_json(const Value& v) {
  return std::visit([](const auto& x) { return json(x); }, v);
}

Value json_to_value(const json& j, ValueType type, const std::string& where) {
  switch (type) {
    case ValueType::number:
      if (!j.is_number()) corrupt(where, "expected a number");
      return j.get<double>();
    case ValueType::integer:
      return integer_value<std::int64_t>(j, where);
    case ValueType::boolean:
      if (!j.is_boolean()) corrupt(where, "expected true or false");
      return j.get<bool>();
    case ValueType::string:
      if (!j.is_string()) corrupt(where, "expected a string");
      return j.get<std::string>();
    case ValueType::array: {
      if (!j.is_array()) corrupt(where, "expected an array of numbers");
      std::vector<double> a;
      for (const auto& x : j) {
        if (!x.is_number()) corrupt(where, "expected an array of numbers");
        a.push_back(x.get<double>());
      }
      return a;
    }
  }
  corrupt(where, "unsupported type");
}

bool fixed_property(const Object& o, const std::string& name) {
  return o.kind == ObjectKind::central_body && (name == "shape" || name == "dimensions_m" || name == "composite" ||
                                                name == "mesh_file" || name == "mesh_materials");
}

json properties_to_json(const Object& o) {
  json p = json::object();
  for (const auto& spec : universe::properties_of(o.kind))
    if (!fixed_property(o, spec.name)) p[spec.name] = value_to_json(spec.get(o));
  return p;
}

// Applies the properties of an object of `kind` through `set(name, value)`,
// in the property table's order (shape before dimensions_m, preset before
// W_rms), so that any order in the file works.
template <class Set>
void apply_properties(ObjectKind kind, const json& p, const std::string& where, const Set& set) {
  if (!p.is_object()) corrupt(where, "expected an object");
  std::set<std::string> seen;
  for (const auto& spec : universe::properties_of(kind)) {
    if (!p.contains(spec.name)) continue;
    seen.insert(spec.name);
    const std::string at = where + "." + spec.name;
    try {
      set(spec.name, json_to_value(p.at(spec.name), spec.type, at));
    } catch (const Error& e) {
      if (e.status() == Status::corrupt_file) throw;
      corrupt(at, e.what());
    }
  }
  for (auto it = p.begin(); it != p.end(); ++it)
    if (!seen.count(it.key())) corrupt(where + "." + it.key(), "unknown property of a " + std::string(kind_name(kind)));
}

json vec(const frames::Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

frames::Vec3 vec_from(const json& j, const std::string& key, const std::string& where) {
  const auto a = field<std::vector<double>>(j, key, where);
  if (a.size() != 3) corrupt(where + "." + key, "expected 3 numbers");
  return frames::Vec3(a[0], a[1], a[2]);
}

ObjectKind kind_from(const std::string& s, const std::string& where) {
  for (int k = 1; k <= static_cast<int>(ObjectKind::site); ++k)
    if (s == universe::kind_name(static_cast<ObjectKind>(k))) return static_cast<ObjectKind>(k);
  corrupt(where, "unknown kind '" + s + "'");
}
}  // namespace

namespace {
// Largest state or sensor file read: 64 MiB (a state of every object the
// limits allow is under 1 MiB; /dev/zero is refused instead of read forever).
constexpr std::size_t max_file_bytes = std::size_t{64} << 20;

std::string read_state_file(const std::string& path) {
  return read_file(path, max_file_bytes, "state and sensor files");
}
}  // namespace

json parse_document(const std::string& text, const std::string& path) {
  return universe::parse_json_document(text, "file '" + path + "'");
}

json engine_to_json(const Engine& engine) {
  json doc;
  doc["format"] = "eoir-scd";
  const universe::ObjectLimits& limits = engine.universe().limits();
  doc["version"] = scd_format_version;
  std::ostringstream rng;
  rng << engine.noise_rng();
  doc["engine"] = {{"seed", engine.options().seed}, {"noise_rng_state", rng.str()}};
  if (!limits.is_default())
    doc["engine"]["limits"] = {{"max_satellites", limits.satellites}, {"max_vehicles", limits.vehicles},
                               {"max_sites", limits.sites},           {"max_missiles", limits.missiles},
                               {"max_sensors", limits.sensors}};
  const EngineTime& t = engine.time();
  doc["time"] = {{"scale", "TT"},
                 {"days_since_j2000", t.days()},
                 {"fraction_of_day", t.fraction()},
                 {"utc", iso_from_utc(t.to(TimeScale::utc), 6)}};
  // The user's materials and spectra before the objects that name them.
  json materials = json::array();
  for (const universe::Material& m : engine.user_materials()) materials.push_back(universe::material_to_json(m));
  doc["materials"] = materials;
  json spectra = json::array();
  for (const universe::NamedSpectrum& s : engine.user_spectra())
    spectra.push_back({{"name", s.name},
                       {"source", s.source},
                       {"wavelength_um", s.radiance_W_cm2_sr_um.wavelengths_um()},
                       {"radiance_W_cm2_sr_um", s.radiance_W_cm2_sr_um.values()}});
  doc["spectra"] = spectra;
  json objects = json::array();
  for (const Object& o : engine.universe().objects()) {
    json j{{"name", o.name}, {"kind", universe::kind_name(o.kind)}};
    if (o.kind == ObjectKind::sensor) j["parent"] = o.parent;
    j["properties"] = properties_to_json(o);
    if (o.state.valid) {
      const auto& s = o.state;
      j["state"] = {{"epoch_days_since_j2000", s.epoch.days()},
                    {"epoch_fraction_of_day", s.epoch.fraction()},
                    {"frame", s.frame == universe::StateFrame::j2000 ? "j2000" : "earth_fixed"},
                    {"position_m", vec(s.position_m)},
                    {"velocity_m_s", vec(s.velocity_m_s)},
                    {"attitude_wxyz", json::array({s.attitude.w(), s.attitude.x(), s.attitude.y(), s.attitude.z()})}};
      if (s.angular_velocity_rad_s != frames::Vec3::Zero()) j["state"]["angular_velocity_rad_s"] = vec(s.angular_velocity_rad_s);
    }
    objects.push_back(j);
  }
  doc["objects"] = objects;
  return doc;
}

std::unique_ptr<Engine> engine_from_json(const json& doc, const EngineOptions& restoring) {
  check_fields(doc, "scd", {"format", "version", "engine", "time", "materials", "spectra", "objects"},
               {"format", "version", "engine", "time", "objects"});
  check_format(doc, "eoir-scd", scd_format_version, "scd");
  const json& e = doc.at("engine");
  check_fields(e, "scd.engine", {"seed", "noise_rng_state", "limits"}, {"seed", "noise_rng_state"});
  EngineOptions options = restoring;
  options.seed = field<std::uint64_t>(e, "seed", "scd.engine");
  auto engine = std::make_unique<Engine>(options);
  if (e.contains("limits")) {
    const json& l = e.at("limits");
    const std::string where = "scd.engine.limits";
    check_fields(l, where, {"max_satellites", "max_vehicles", "max_sites", "max_missiles", "max_sensors"},
                 {"max_satellites", "max_vehicles", "max_sites", "max_missiles", "max_sensors"});
    universe::ObjectLimits limits;
    limits.satellites = field<std::size_t>(l, "max_satellites", where);
    limits.vehicles = field<std::size_t>(l, "max_vehicles", where);
    limits.sites = field<std::size_t>(l, "max_sites", where);
    limits.missiles = field<std::size_t>(l, "max_missiles", where);
    limits.sensors = field<std::size_t>(l, "max_sensors", where);
    try {
      engine->set_limits(limits);
    } catch (const Error& err) {
      corrupt(where, err.what());
    }
  }
  {
    std::mt19937_64 rng;
    std::istringstream in(field<std::string>(e, "noise_rng_state", "scd.engine"));
    in >> rng;
    if (in.fail()) corrupt("scd.engine.noise_rng_state", "not a generator state");
    engine->set_noise_rng(rng);
  }
  const json& t = doc.at("time");
  check_fields(t, "scd.time", {"scale", "days_since_j2000", "fraction_of_day", "utc"},
               {"scale", "days_since_j2000", "fraction_of_day"});
  if (field<std::string>(t, "scale", "scd.time") != "TT") corrupt("scd.time.scale", "must be 'TT'");
  try {
    engine->set_time(EngineTime::from_tt_days(field<double>(t, "days_since_j2000", "scd.time"),
                                              field<double>(t, "fraction_of_day", "scd.time")));
  } catch (const Error& err) {
    corrupt("scd.time", err.what());
  }
  if (doc.contains("materials")) {
    const json& materials = doc.at("materials");
    if (!materials.is_array()) corrupt("scd.materials", "expected an array");
    for (std::size_t i = 0; i < materials.size(); ++i) {
      const std::string where = "scd.materials[" + std::to_string(i) + "]";
      const universe::Material m = universe::material_from_json(materials[i], where);
      try {
        engine->add_material(m);
      } catch (const Error& err) {
        corrupt(where, err.what());
      }
    }
  }
  if (doc.contains("spectra")) {
    const json& spectra = doc.at("spectra");
    if (!spectra.is_array()) corrupt("scd.spectra", "expected an array");
    for (std::size_t i = 0; i < spectra.size(); ++i) {
      const std::string where = "scd.spectra[" + std::to_string(i) + "]";
      const json& s = spectra[i];
      check_fields(s, where, {"name", "source", "wavelength_um", "radiance_W_cm2_sr_um"},
                   {"name", "wavelength_um", "radiance_W_cm2_sr_um"});
      try {
        universe::NamedSpectrum spectrum{field<std::string>(s, "name", where),
                                         optional_field<std::string>(s, "source", std::string(), where),
                                         TabulatedFunction(field<std::vector<double>>(s, "wavelength_um", where),
                                                           field<std::vector<double>>(s, "radiance_W_cm2_sr_um", where),
                                                           where + ".radiance_W_cm2_sr_um")};
        engine->add_spectrum(spectrum);
      } catch (const Error& err) {
        if (err.status() == Status::corrupt_file) throw;
        corrupt(where, err.what());
      }
    }
  }
  const json& objects = doc.at("objects");
  if (!objects.is_array()) corrupt("scd.objects", "expected an array");
  for (size_t i = 0; i < objects.size(); ++i) {
    const std::string where = "scd.objects[" + std::to_string(i) + "]";
    const json& j = objects[i];
    check_fields(j, where, {"name", "kind", "parent", "properties", "state"}, {"name", "kind"});
    const auto name = field<std::string>(j, "name", where);
    const ObjectKind kind = kind_from(field<std::string>(j, "kind", where), where + ".kind");
    try {
      const universe::Object* existing = engine->universe().find(name);
      const bool the_sun = existing && existing->kind == ObjectKind::central_body && kind == ObjectKind::central_body &&
                           existing->central_body == universe::CentralBody::sun;
      if (the_sun) {
        // always present
      } else if (kind == ObjectKind::sensor) {
        engine->add_sensor(name, optional_field<std::string>(j, "parent", std::string(), where));
      } else {
        engine->add_object(kind, name);
      }
    } catch (const Error& err) {
      corrupt(where, err.what());
    }
    if (j.contains("properties"))
      apply_properties(kind, j.at("properties"), where + ".properties",
                       [&](const std::string& property, const Value& v) { engine->set_property(name, property, v); });
    if (j.contains("state")) {
      const json& s = j.at("state");
      const std::string sw = where + ".state";
      check_fields(s, sw,
                   {"epoch_days_since_j2000", "epoch_fraction_of_day", "frame", "position_m", "velocity_m_s",
                    "attitude_wxyz", "angular_velocity_rad_s"},
                   {"epoch_days_since_j2000", "epoch_fraction_of_day", "frame", "position_m", "velocity_m_s",
                    "attitude_wxyz"});
      const auto frame = field<std::string>(s, "frame", sw);
      if (frame != "j2000" && frame != "earth_fixed") corrupt(sw + ".frame", "must be j2000 or earth_fixed");
      const auto q = field<std::vector<double>>(s, "attitude_wxyz", sw);
      if (q.size() != 4) corrupt(sw + ".attitude_wxyz", "expected 4 numbers");
      const frames::Vec3 r = vec_from(s, "position_m", sw), v = vec_from(s, "velocity_m_s", sw);
      try {
        universe::PushedState state;
        state.valid = true;
        state.epoch = EngineTime::from_tt_days(field<double>(s, "epoch_days_since_j2000", sw),
                                               field<double>(s, "epoch_fraction_of_day", sw));
        state.frame = frame == "j2000" ? universe::StateFrame::j2000 : universe::StateFrame::earth_fixed;
        state.position_m = r;
        state.velocity_m_s = v;
        state.attitude = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);  // kept bit for bit
        if (s.contains("angular_velocity_rad_s")) state.angular_velocity_rad_s = vec_from(s, "angular_velocity_rad_s", sw);
        engine->restore_state(name, state);
      } catch (const Error& err) {
        corrupt(sw, err.what());
      }
    }
  }
  return engine;
}

json sensor_to_json(const Object& s) {
  return json{{"format", "eoir-sensor"},
              {"version", sensor_format_version},
              {"name", s.name},
              {"parameters", properties_to_json(s)}};
}

sensor::SensorParameters sensor_from_json(const json& doc) {
  check_fields(doc, "sensor", {"format", "version", "name", "parameters"}, {"format", "version", "parameters"});
  check_format(doc, "eoir-sensor", sensor_format_version, "sensor");
  Object o;
  o.kind = ObjectKind::sensor;
  o.name = optional_field<std::string>(doc, "name", std::string("sensor"), "sensor");
  apply_properties(ObjectKind::sensor, doc.at("parameters"), "sensor.parameters",
                   [&](const std::string& property, const Value& v) { universe::set_property(o, property, v); });
  try {
    universe::validate(o.sensor);
  } catch (const Error& err) {
    corrupt("sensor.parameters", err.what());
  }
  return o.sensor;
}

void save_engine(const Engine& engine, const std::string& path) {
  write_file_atomically(path, engine_to_json(engine).dump(1) + "\n");
}

std::unique_ptr<Engine> load_engine(const std::string& path, const EngineOptions& options) {
  return engine_from_json(parse_document(read_state_file(path), path), options);
}

void save_sensor(const Object& sensor, const std::string& path) {
  write_file_atomically(path, sensor_to_json(sensor).dump(1) + "\n");
}

sensor::SensorParameters load_sensor(const std::string& path) {
  return sensor_from_json(parse_document(read_state_file(path), path));
}

}  // namespace eoir::state
