#include "scenario.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "iso_time.hpp"
#include "json_guard.hpp"
#include "suggest.hpp"
#include "time_steps.hpp"
#include "tle_file.hpp"

namespace eoir::cli {
namespace {

using nlohmann::json;
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kEarthEquatorialRadiusM = 6378137.0;  // WGS84
constexpr double kMaxOrbitRadiusM = 1e14;               // the engine's positions (README "Bounds")

[[noreturn]] void fail(const std::string& path, const std::string& why) { throw ScenarioError(path + ": " + why); }

const char* type_name(const json& j) { return j.type_name(); }

void only_keys(const json& obj, const std::string& path, std::initializer_list<const char*> allowed) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || it.key() == a;
    if (!ok) fail(path + "." + it.key(), "unknown field");
  }
}

const json& need(const json& obj, const std::string& path, const char* key) {
  auto it = obj.find(key);
  if (it == obj.end()) fail(path, std::string("missing required field '") + key + "'");
  return *it;
}

const json& need_object(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, std::string("must be an object, not ") + type_name(j));
  return j;
}

double get_number(const json& obj, const std::string& path, const char* key) {
  const json& j = need(obj, path, key);
  if (!j.is_number()) fail(path + "." + key, std::string("must be a number, not ") + type_name(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path + "." + key, "must be finite");
  return v;
}

double get_number_or(const json& obj, const std::string& path, const char* key, double fallback) {
  return obj.contains(key) ? get_number(obj, path, key) : fallback;
}

std::string get_string(const json& obj, const std::string& path, const char* key) {
  const json& j = need(obj, path, key);
  if (!j.is_string()) fail(path + "." + key, std::string("must be a string, not ") + type_name(j));
  return j.get<std::string>();
}

double get_time(const json& obj, const std::string& path, const char* key) {
  const std::string s = get_string(obj, path, key);
  try {
    return parse_iso(s);
  } catch (const std::invalid_argument& e) {
    fail(path + "." + key, e.what());
  }
}

Vec3 get_vec3(const json& obj, const std::string& path, const char* key) {
  const json& j = need(obj, path, key);
  if (!j.is_array() || j.size() != 3) fail(path + "." + key, "must be an array of 3 numbers");
  Vec3 v{};
  for (std::size_t i = 0; i < 3; ++i) {
    if (!j[i].is_number()) fail(path + "." + key + "[" + std::to_string(i) + "]", "must be a number");
    v[i] = j[i].get<double>();
  }
  return v;
}

void check_name(const std::string& name, const std::string& path) {
  if (name.empty() || name.size() > 63) fail(path, "names are 1 to 63 bytes");
}

// An orbit whose perigee lies below the central body's surface would pass
// through it (the engine would place the satellite inside the Earth).
void check_perigee(double perigee_m, const std::string& path) {
  if (perigee_m < kEarthEquatorialRadiusM) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "perigee radius %.3f km is below the surface of the Earth (equatorial radius %.3f km): "
                  "the orbit passes through the central body",
                  perigee_m / 1e3, kEarthEquatorialRadiusM / 1e3);
    fail(path, text);
  }
}

// A file named by property `path` of the scenario `file` (ScenarioOptions):
// the path to read, relative to the scenario's folder; refused outside it
// with one message whether the file exists or not.
std::string named_file(const std::string& file, const std::string& named, const std::string& path,
                       const ScenarioOptions& options) {
  namespace fs = std::filesystem;
  const fs::path folder = fs::path(file).parent_path();
  const fs::path resolved = (fs::path(named).is_relative() ? folder / named : fs::path(named)).lexically_normal();
  if (options.allow_paths_outside) return resolved.string();
  std::error_code folder_error, file_error;
  const fs::path base = fs::weakly_canonical(fs::absolute(folder.empty() ? fs::path(".") : folder), folder_error);
  const fs::path real = fs::weakly_canonical(fs::absolute(resolved), file_error);
  const fs::path inside = real.lexically_relative(base);
  if (folder_error || file_error || inside.empty() || *inside.begin() == "..")
    fail(path, "'" + named + "' lies outside the scenario's folder; files a scenario names are relative to it and "
                             "inside it (eoir --allow-paths-outside, Python allow_paths_outside=True: read others)");
  return resolved.string();
}

// Resolves the mesh files of a composite's parts (nested parts too).
void resolve_part_files(json& parts, const std::string& file, const std::string& path, const ScenarioOptions& options) {
  if (!parts.is_array()) return;  // (the engine says what is wrong with it)
  for (std::size_t i = 0; i < parts.size(); ++i) {
    json& part = parts[i];
    if (!part.is_object()) continue;
    const std::string at = path + "[" + std::to_string(i) + "]";
    if (part.contains("mesh_file") && part["mesh_file"].is_string() && !part["mesh_file"].get<std::string>().empty())
      part["mesh_file"] = named_file(file, part["mesh_file"].get<std::string>(), at + ".mesh_file", options);
    if (part.contains("parts")) resolve_part_files(part["parts"], file, at + ".parts", options);
  }
}

// Resolves every file-valued property (named *_file) of a properties object,
// and the mesh files a composite's parts name.
void resolve_named_files(json& properties, const std::string& file, const std::string& path,
                         const ScenarioOptions& options) {
  for (auto it = properties.begin(); it != properties.end(); ++it) {
    const std::string& key = it.key();
    const bool names_file = key.size() > 5 && key.compare(key.size() - 5, 5, "_file") == 0;
    if (names_file && it->is_string() && !it->get<std::string>().empty())
      *it = named_file(file, it->get<std::string>(), path + "." + key, options);
    if (key == "composite" && it->is_string()) {
      json parts = json::parse(it->get<std::string>(), nullptr, false);
      if (parts.is_array()) {
        resolve_part_files(parts, file, path + ".composite", options);
        *it = parts.dump();
      }
    }
  }
}

Attitude parse_attitude(const json& j, const std::string& path, bool sensor) {
  need_object(j, path);
  Attitude a;
  const std::string type = get_string(j, path, "type");
  if (type == "fixed_inertial") {
    only_keys(j, path, {"type", "quaternion"});
    const json& q = need(j, path, "quaternion");
    if (!q.is_array() || q.size() != 4) fail(path + ".quaternion", "must be [w, x, y, z]");
    for (std::size_t i = 0; i < 4; ++i) {
      if (!q[i].is_number()) fail(path + ".quaternion[" + std::to_string(i) + "]", "must be a number");
      a.quaternion[i] = q[i].get<double>();
    }
    try {
      a.quaternion = normalize(a.quaternion);
    } catch (const std::domain_error&) {
      fail(path + ".quaternion", "must be a non-zero quaternion");
    }
    a.type = Attitude::Type::fixed_inertial;
  } else if (type == "spinning_inertial") {
    only_keys(j, path, {"type", "quaternion", "axis_body", "rate_deg_s", "epoch"});
    a = parse_attitude(json{{"type", "fixed_inertial"}, {"quaternion", need(j, path, "quaternion")}}, path, sensor);
    a.type = Attitude::Type::spinning_inertial;
    a.axis_body = get_vec3(j, path, "axis_body");
    try {
      a.axis_body = normalize(a.axis_body);
    } catch (const std::domain_error&) {
      fail(path + ".axis_body", "must be a non-zero vector");
    }
    a.rate_deg_s = get_number(j, path, "rate_deg_s");
    if (!(std::fabs(a.rate_deg_s) <= 1e4)) fail(path + ".rate_deg_s", "must be within +-1e4 deg/s");
    a.epoch_s = j.contains("epoch") ? get_time(j, path, "epoch") : std::nan("");
  } else if (type == "nadir") {
    only_keys(j, path, {"type"});
    a.type = Attitude::Type::nadir;
  } else if (type == "target") {
    only_keys(j, path, {"type", "target"});
    a.target = get_string(j, path, "target");
    a.type = Attitude::Type::target;
  } else if (type == "azel" && sensor) {
    only_keys(j, path, {"type", "azimuth_deg", "elevation_deg"});
    a.azimuth_deg = get_number(j, path, "azimuth_deg");
    a.elevation_deg = get_number(j, path, "elevation_deg");
    if (std::fabs(a.azimuth_deg) > 360) fail(path + ".azimuth_deg", "must be in [-360, 360]");
    if (std::fabs(a.elevation_deg) > 90) fail(path + ".elevation_deg", "must be in [-90, 90]");
    a.type = Attitude::Type::azel;
  } else if (type == "azel") {
    fail(path + ".type", "'azel' points sensors only (a sensor's pointing)");
  } else if (type == "heading_pitch_roll" && !sensor) {
    only_keys(j, path, {"type", "heading_deg", "pitch_deg", "roll_deg"});
    a.heading_deg = get_number_or(j, path, "heading_deg", 0.0);
    a.pitch_deg = get_number_or(j, path, "pitch_deg", 0.0);
    a.roll_deg = get_number_or(j, path, "roll_deg", 0.0);
    if (std::fabs(a.heading_deg) > 360) fail(path + ".heading_deg", "must be in [-360, 360]");
    if (std::fabs(a.pitch_deg) > 90) fail(path + ".pitch_deg", "must be in [-90, 90]");
    if (std::fabs(a.roll_deg) > 180) fail(path + ".roll_deg", "must be in [-180, 180]");
    a.type = Attitude::Type::heading_pitch_roll;
  } else if (type == "heading_pitch_roll") {
    fail(path + ".type", "'heading_pitch_roll' turns objects only (aircraft, ground vehicles...)");
  } else if (type == "velocity" && !sensor) {
    only_keys(j, path, {"type"});
    a.type = Attitude::Type::velocity;
  } else {
    const std::vector<std::string> types = sensor ? std::vector<std::string>{"fixed_inertial", "spinning_inertial",
                                                                             "nadir", "target", "azel"}
                                                  : std::vector<std::string>{"fixed_inertial", "spinning_inertial",
                                                                             "nadir", "target", "heading_pitch_roll", "velocity"};
    std::string list;
    for (const auto& t : types) list += (list.empty() ? "" : ", ") + t;
    fail(path + ".type", "'" + type + "' is not one of " + list + did_you_mean(type, types));
  }
  return a;
}

Motion parse_motion(const json& j, const std::string& path) {
  need_object(j, path);
  Motion m;
  const std::string type = get_string(j, path, "type");
  if (type == "fixed_geodetic") {
    only_keys(j, path, {"type", "lat_deg", "lon_deg", "alt_m"});
    m.kind = Motion::Kind::fixed_geodetic;
    m.lat_deg = get_number(j, path, "lat_deg");
    m.lon_deg = get_number(j, path, "lon_deg");
    m.alt_m = get_number_or(j, path, "alt_m", 0.0);
    if (std::fabs(m.lat_deg) > 90) fail(path + ".lat_deg", "must be in [-90, 90]");
  } else if (type == "kepler") {
    only_keys(j, path, {"type", "central_body", "semi_major_axis_km", "eccentricity", "inclination_deg", "raan_deg",
                        "arg_perigee_deg", "true_anomaly_deg", "mean_anomaly_deg", "epoch"});
    if (j.contains("central_body") && get_string(j, path, "central_body") != "Earth")
      fail(path + ".central_body", "only \"Earth\" is supported");
    KeplerElements el;
    const double a_km = get_number(j, path, "semi_major_axis_km");
    el.semi_major_axis_m = a_km * 1e3;
    el.eccentricity = get_number_or(j, path, "eccentricity", 0.0);
    el.inclination = get_number_or(j, path, "inclination_deg", 0.0) * kDeg;
    el.raan = get_number_or(j, path, "raan_deg", 0.0) * kDeg;
    el.arg_perigee = get_number_or(j, path, "arg_perigee_deg", 0.0) * kDeg;
    if (!(a_km > 0)) fail(path + ".semi_major_axis_km", "must be positive, got " + json(a_km).dump());
    if (!(el.eccentricity >= 0 && el.eccentricity < 1)) fail(path + ".eccentricity", "must be in [0, 1)");
    if (!(el.semi_major_axis_m * (1 + el.eccentricity) <= kMaxOrbitRadiusM))
      fail(path + ".semi_major_axis_km", json(a_km).dump() + " km puts the apogee beyond 1e11 km (the engine places "
                                         "objects within 1e14 m of the Earth)");
    const bool has_true = j.contains("true_anomaly_deg"), has_mean = j.contains("mean_anomaly_deg");
    if (has_true && has_mean) fail(path, "give true_anomaly_deg or mean_anomaly_deg, not both");
    if (has_mean)
      el.mean_anomaly_at_epoch = get_number(j, path, "mean_anomaly_deg") * kDeg;
    else
      el.mean_anomaly_at_epoch =
          true_to_mean_anomaly(get_number_or(j, path, "true_anomaly_deg", 0.0) * kDeg, el.eccentricity);
    el.epoch_s = get_time(j, path, "epoch");
    check_perigee(el.semi_major_axis_m * (1 - el.eccentricity), path);
    try {
      m.kepler = std::make_shared<KeplerOrbit>(el);
    } catch (const std::invalid_argument& e) {
      fail(path, e.what());
    }
    m.kind = Motion::Kind::kepler;
  } else if (type == "ephemeris") {
    only_keys(j, path, {"type", "frame", "points"});
    const std::string frame = get_string(j, path, "frame");
    if (frame != "j2000" && frame != "earth_fixed") fail(path + ".frame", "must be \"j2000\" or \"earth_fixed\"");
    m.earth_fixed = frame == "earth_fixed";
    const json& pts = need(j, path, "points");
    if (!pts.is_array()) fail(path + ".points", "must be an array");
    std::vector<EphemerisPoint> points;
    bool with_velocity = true;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const std::string p = path + ".points[" + std::to_string(i) + "]";
      need_object(pts[i], p);
      only_keys(pts[i], p, {"time", "position_m", "velocity_m_s"});
      EphemerisPoint e;
      e.t_s = get_time(pts[i], p, "time");
      e.position = get_vec3(pts[i], p, "position_m");
      const bool v = pts[i].contains("velocity_m_s");
      if (i > 0 && v != with_velocity) fail(p, "give velocity_m_s at every point or at none");
      with_velocity = v;
      if (v) e.velocity = get_vec3(pts[i], p, "velocity_m_s");
      points.push_back(e);
    }
    try {
      m.ephemeris = std::make_shared<Ephemeris>(std::move(points), with_velocity);
    } catch (const std::invalid_argument& e) {
      fail(path, e.what());
    }
    m.kind = Motion::Kind::ephemeris;
  } else if (type == "tle") {
    only_keys(j, path, {"type", "line1", "line2"});
    const std::string l1 = get_string(j, path, "line1"), l2 = get_string(j, path, "line2");
    try {
      m.tle = std::make_shared<Sgp4>(Sgp4::from_tle(l1, l2));
    } catch (const std::invalid_argument& e) {
      const std::string why = e.what();
      fail(path + (why.rfind("line 1", 0) == 0 ? ".line1" : ".line2"), why);
    }
    check_perigee(m.tle->perigee_radius_km() * 1e3, path);
    m.kind = Motion::Kind::tle;
  } else if (type == "ballistic") {
    only_keys(j, path, {"type", "launch_lat_deg", "launch_lon_deg", "impact_lat_deg", "impact_lon_deg", "launch_time",
                        "burn_s", "apogee_height_m"});
    double v[4];
    const char* names[4] = {"launch_lat_deg", "launch_lon_deg", "impact_lat_deg", "impact_lon_deg"};
    for (int k = 0; k < 4; ++k) {
      v[k] = get_number(j, path, names[k]);
      if (std::fabs(v[k]) > (k % 2 ? 360.0 : 90.0))
        fail(path + "." + names[k], k % 2 ? "must be in [-360, 360]" : "must be in [-90, 90]");
    }
    const double launch = get_time(j, path, "launch_time");
    const double burn = get_number(j, path, "burn_s");
    const double apogee = j.contains("apogee_height_m") ? get_number(j, path, "apogee_height_m") : std::nan("");
    try {
      m.ballistic = std::make_shared<BallisticArc>(v[0], v[1], v[2], v[3], launch, burn, apogee);
    } catch (const std::invalid_argument& e) {
      const std::string why = e.what();
      const auto colon = why.find(':');
      fail(path + (colon == std::string::npos ? "" : "." + why.substr(0, colon)),
           colon == std::string::npos ? why : why.substr(colon + 2));
    }
    m.kind = Motion::Kind::ballistic;
  } else {
    fail(path + ".type", "'" + type + "' is not one of fixed_geodetic, kepler, ephemeris, tle, ballistic" +
                             did_you_mean(type, {"fixed_geodetic", "kepler", "ephemeris", "tle", "ballistic"}));
  }
  return m;
}

// objects[i] {"tle_file": F, "kind", "attitude", "properties"}: one object
// per set of F (tle_file.hpp), named by its title line, on SGP4, each with
// the entry's kind, attitude and properties.
void add_tle_file(const json& entry, const std::string& path, const std::string& file,
                  const ScenarioOptions& options, std::set<std::string>& names, std::vector<ObjectSpec>& objects) {
  only_keys(entry, path, {"tle_file", "kind", "attitude", "properties"});
  const std::string kind = get_string(entry, path, "kind");
  if (kind != "satellite" && kind != "missile")
    fail(path + ".kind", "'" + kind + "' cannot move on two-line elements: satellite or missile");
  const std::string named = get_string(entry, path, "tle_file");
  if (named.empty()) fail(path + ".tle_file", "must name a file");
  const std::string tle_path = named_file(file, named, path + ".tle_file", options);
  std::vector<TleSet> sets;
  try {
    sets = parse_tle_file(read_file_capped(tle_path));
  } catch (const JsonInputError& e) {
    fail(path + ".tle_file", e.what());
  } catch (const std::invalid_argument& e) {
    fail(path + ".tle_file", "'" + named + "' " + e.what());
  }
  Attitude attitude;
  if (entry.contains("attitude")) attitude = parse_attitude(entry["attitude"], path + ".attitude", false);
  json properties = json::object();
  if (entry.contains("properties")) properties = need_object(entry["properties"], path + ".properties");
  for (TleSet& set : sets) {
    ObjectSpec o;
    o.path = path + ".tle_file line " + std::to_string(set.title_line);
    o.name = set.name;
    if (!names.insert(o.name).second) fail(o.path, "an object named '" + o.name + "' exists already");
    o.kind = kind;
    o.motion.kind = Motion::Kind::tle;
    o.motion.tle = std::make_shared<Sgp4>(std::move(set.sgp4));
    check_perigee(o.motion.tle->perigee_radius_km() * 1e3, o.path);
    o.attitude = attitude;
    o.properties = properties;
    objects.push_back(std::move(o));
  }
}

}  // namespace

const ObjectSpec* Scenario::find_object(const std::string& n) const {
  for (const auto& o : objects)
    if (o.name == n) return &o;
  return nullptr;
}

const SensorSpec* Scenario::find_sensor(const std::string& n) const {
  for (const auto& s : sensors)
    if (s.name == n) return &s;
  return nullptr;
}

Scenario parse_scenario(const json& doc, const std::string& file, const ScenarioOptions& options) {
  Scenario sc;
  sc.file = file;
  const std::string root = "scenario";
  if (!doc.is_object()) fail(root, "must be a JSON object");
  only_keys(doc, "", {"$schema", "format", "version", "name", "description", "start", "stop", "step_s", "limits",
                      "central_bodies", "stars", "objects", "sensors"});
  if (get_string(doc, root, "format") != "eoir-scenario") fail("format", "must be \"eoir-scenario\"");
  const json& version = need(doc, root, "version");
  if (!version.is_number_integer()) fail("version", "must be an integer");
  if (version.get<long long>() > 1)
    fail("version", "written by a newer format version (" + version.dump() + "); this program reads version 1");
  if (version.get<long long>() < 1) fail("version", "must be 1");
  sc.name = get_string(doc, root, "name");
  if (doc.contains("description")) sc.description = get_string(doc, root, "description");
  try {
    sc.start_s = parse_iso(get_string(doc, root, "start"));
  } catch (const std::invalid_argument& e) {
    fail("start", e.what());
  }
  try {
    sc.stop_s = doc.contains("stop") ? parse_iso(get_string(doc, root, "stop")) : sc.start_s;
  } catch (const std::invalid_argument& e) {
    fail("stop", e.what());
  }
  if (sc.stop_s < sc.start_s) fail("stop", "is before start");
  sc.step_s = get_number_or(doc, root, "step_s", 60.0);
  try {
    check_step(sc.step_s, "step_s");
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(e.what());
  }

  if (doc.contains("limits")) {
    // Each in [1, its ceiling] (eoir.h EOIR_CEILING_*; the engine checks).
    const json& l = need_object(doc["limits"], "limits");
    only_keys(l, "limits", {"max_satellites", "max_vehicles", "max_sites", "max_missiles", "max_sensors"});
    const auto limit = [&](const char* key) -> std::uint32_t {
      if (!l.contains(key)) return 0;
      const json& v = l[key];
      if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1000000)
        fail(std::string("limits.") + key, "must be a whole number of at least 1, not " + v.dump());
      return static_cast<std::uint32_t>(v.get<long long>());
    };
    sc.limits.max_satellites = limit("max_satellites");
    sc.limits.max_vehicles = limit("max_vehicles");
    sc.limits.max_sites = limit("max_sites");
    sc.limits.max_missiles = limit("max_missiles");
    sc.limits.max_sensors = limit("max_sensors");
    sc.limits.given = true;
  }

  static const std::set<std::string> bodies{"Sun",     "Mercury", "Venus",  "Earth",   "Mars",
                                            "Jupiter", "Saturn",  "Uranus", "Neptune", "Moon"};
  std::set<std::string> names{"Sun"};
  if (doc.contains("central_bodies")) {
    const json& cb = doc["central_bodies"];
    if (!cb.is_array()) fail("central_bodies", "must be an array of names or {\"name\", \"properties\"} objects");
    for (std::size_t i = 0; i < cb.size(); ++i) {
      const std::string p = "central_bodies[" + std::to_string(i) + "]";
      const json* name = &cb[i];
      if (cb[i].is_object()) {
        only_keys(cb[i], p, {"name", "properties"});
        name = &need(cb[i], p, "name");
        if (cb[i].contains("properties")) {
          if (!cb[i]["properties"].is_object()) fail(p + ".properties", "must be an object");
        }
      }
      const std::string np = cb[i].is_object() ? p + ".name" : p;
      if (!name->is_string() || !bodies.count(name->get<std::string>()))
        fail(np, "must be one of Sun, Mercury, Venus, Earth, Mars, Jupiter, Saturn, Uranus, Neptune, Moon");
      const std::string b = name->get<std::string>();
      if (b != "Sun" && !names.insert(b).second) fail(np, "'" + b + "' is listed twice");
      if (b != "Sun") sc.central_bodies.push_back(b);
      if (cb[i].is_object() && cb[i].contains("properties"))
        sc.body_properties.push_back({b, cb[i]["properties"], p});
    }
  }
  if (doc.contains("stars")) {
    // true, false, or {"properties": {...}} of the star field "Stars".
    const json& st = doc["stars"];
    if (st.is_object()) {
      only_keys(st, "stars", {"properties"});
      sc.stars = true;
      if (st.contains("properties")) {
        if (!st["properties"].is_object()) fail("stars.properties", "must be an object");
        sc.body_properties.push_back({"Stars", st["properties"], "stars"});
      }
    } else if (st.is_boolean()) {
      sc.stars = st.get<bool>();
    } else {
      fail("stars", "must be true, false or {\"properties\": {...}}");
    }
    if (sc.stars) names.insert("Stars");
  }

  if (doc.contains("objects")) {
    const json& objs = doc["objects"];
    if (!objs.is_array()) fail("objects", "must be an array");
    for (std::size_t i = 0; i < objs.size(); ++i) {
      ObjectSpec o;
      o.path = "objects[" + std::to_string(i) + "]";
      need_object(objs[i], o.path);
      if (objs[i].contains("tle_file")) {
        add_tle_file(objs[i], o.path, file, options, names, sc.objects);
        continue;
      }
      only_keys(objs[i], o.path, {"name", "kind", "motion", "attitude", "properties"});
      o.name = get_string(objs[i], o.path, "name");
      check_name(o.name, o.path + ".name");
      if (!names.insert(o.name).second) fail(o.path + ".name", "an object named '" + o.name + "' exists already");
      o.kind = get_string(objs[i], o.path, "kind");
      static const std::vector<std::string> kinds{"satellite", "aircraft", "ground_vehicle", "missile", "site"};
      if (!std::count(kinds.begin(), kinds.end(), o.kind))
        fail(o.path + ".kind", "'" + o.kind + "' is not one of satellite, aircraft, ground_vehicle, missile, site" +
                                   did_you_mean(o.kind, kinds));
      o.motion = parse_motion(need(objs[i], o.path, "motion"), o.path + ".motion");
      if (o.kind == "site" && o.motion.kind != Motion::Kind::fixed_geodetic)
        fail(o.path + ".motion.type", "a site is fixed on the Earth: its motion must be fixed_geodetic");
      if (o.kind == "site" && objs[i].contains("attitude"))
        fail(o.path + ".attitude", "a site's attitude is its local horizon (east, north, up); point its sensors "
                                   "with their pointing instead");
      if (objs[i].contains("attitude")) o.attitude = parse_attitude(objs[i]["attitude"], o.path + ".attitude", false);
      if (o.attitude.type == Attitude::Type::velocity && o.motion.kind == Motion::Kind::fixed_geodetic)
        fail(o.path + ".attitude.type", "velocity: a fixed_geodetic motion has no velocity");
      if (objs[i].contains("properties")) o.properties = need_object(objs[i]["properties"], o.path + ".properties");
      sc.objects.push_back(std::move(o));
    }
  }
  if (doc.contains("sensors")) {
    const json& sens = doc["sensors"];
    if (!sens.is_array()) fail("sensors", "must be an array");
    for (std::size_t i = 0; i < sens.size(); ++i) {
      SensorSpec s;
      s.path = "sensors[" + std::to_string(i) + "]";
      need_object(sens[i], s.path);
      only_keys(sens[i], s.path, {"name", "parent", "pointing", "parameters"});
      s.name = get_string(sens[i], s.path, "name");
      check_name(s.name, s.path + ".name");
      if (!names.insert(s.name).second) fail(s.path + ".name", "an object named '" + s.name + "' exists already");
      s.parent = get_string(sens[i], s.path, "parent");
      if (!sc.find_object(s.parent) && !std::count(sc.central_bodies.begin(), sc.central_bodies.end(), s.parent) &&
          s.parent != "Sun")
        fail(s.path + ".parent", "unknown object '" + s.parent + "'");
      if (sens[i].contains("pointing")) s.pointing = parse_attitude(sens[i]["pointing"], s.path + ".pointing", true);
      if (sens[i].contains("parameters"))
        s.parameters = need_object(sens[i]["parameters"], s.path + ".parameters");
      sc.sensors.push_back(std::move(s));
    }
  }
  // Attitude targets must name something in the scenario.
  const auto check_target = [&](const Attitude& a, const std::string& path, const std::string& self) {
    if (a.type != Attitude::Type::target) return;
    if (!names.count(a.target)) fail(path + ".target", "unknown object '" + a.target + "'");
    if (a.target == self) fail(path + ".target", "an object cannot point at itself");
  };
  for (const auto& o : sc.objects) check_target(o.attitude, o.path + ".attitude", o.name);
  for (const auto& s : sc.sensors) check_target(s.pointing, s.path + ".pointing", s.parent);
  // Every property object a session applies: the files they name.
  for (auto& b : sc.body_properties) resolve_named_files(b.properties, file, b.path + ".properties", options);
  for (auto& o : sc.objects) resolve_named_files(o.properties, file, o.path + ".properties", options);
  for (auto& s : sc.sensors) resolve_named_files(s.parameters, file, s.path + ".parameters", options);
  return sc;
}

Scenario load_scenario(const std::string& file, const ScenarioOptions& options) {
  json doc;
  try {
    std::string text;
    try {
      text = read_file_capped(file);
    } catch (const JsonInputError& e) {
      const std::string why = e.what();
      throw ScenarioError(why.rfind("cannot open", 0) == 0 ? "cannot open the scenario file (" + why + ")" : why);
    }
    doc = parse_json_checked(text);  // depth, duplicate keys, number range
  } catch (const JsonInputError& e) {
    throw ScenarioError(file + ": " + e.what());
  } catch (const ScenarioError& e) {
    throw ScenarioError(file + ": " + e.what());
  }
  try {
    return parse_scenario(doc, file, options);
  } catch (const ScenarioError& e) {
    throw ScenarioError(file + ": " + e.what());
  }
}

PosVel motion_state(const ObjectSpec& o, double t) {
  const Motion& m = o.motion;
  switch (m.kind) {
    case Motion::Kind::fixed_geodetic:
      return PosVel{{m.lat_deg, m.lon_deg, m.alt_m}, {0, 0, 0}};
    case Motion::Kind::kepler:
      return m.kepler->at(t);
    case Motion::Kind::ephemeris:
      try {
        return m.ephemeris->at(t);
      } catch (const std::out_of_range& e) {
        throw ScenarioError(o.path + ".motion: " + e.what());
      }
    case Motion::Kind::ballistic:
      return m.ballistic->at(t);
    case Motion::Kind::tle:
      try {
        return tle_state_j2000(*m.tle, t);
      } catch (const Sgp4Error& e) {
        throw ScenarioError(o.path + ".motion: SGP4 at " + format_iso(t) + ": " + e.what());
      } catch (const std::invalid_argument& e) {
        throw ScenarioError(o.path + ".motion: " + e.what());
      }
  }
  throw ScenarioError(o.path + ".motion: unknown kind");
}

PosVel tle_state_j2000(const Sgp4& sgp4, double t) {
  // Minutes since the TLE epoch on the UTC time line (days of 86400 s, as
  // SGP4's Julian dates count them).
  const double minutes = ((2451545.0 - sgp4.epoch_jd()) - sgp4.epoch_jd_fraction()) * 1440.0 + t / 60.0;
  const TemeState teme = sgp4.at_minutes(minutes);
  const std::array<double, 9> m = teme_to_j2000_matrix(2451545.0, t / 86400.0);
  PosVel out;
  for (int i = 0; i < 3; ++i) {
    out.position[i] = 1e3 * (m[3 * i] * teme.r_km[0] + m[3 * i + 1] * teme.r_km[1] + m[3 * i + 2] * teme.r_km[2]);
    out.velocity[i] =
        1e3 * (m[3 * i] * teme.v_km_s[0] + m[3 * i + 1] * teme.v_km_s[1] + m[3 * i + 2] * teme.v_km_s[2]);
  }
  return out;
}

}  // namespace eoir::cli
