// The scenario file of the eoir CLI (schemas/scenario.schema.json): parsed
// and checked here, with errors that name the JSON path of the bad field,
// e.g. "objects[2].motion.eccentricity: must be in [0, 1)".
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "motion.hpp"
#include "sgp4.hpp"

namespace eoir::cli {

// A problem in the scenario (bad field, or a motion evaluated out of range).
// what() is "PATH: message".
class ScenarioError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Attitude {
  // azel: sensors only, pointed by the engine (eoir_sensor_point_azel); a
  // sensor on a site tracks its target through eoir_sensor_point_at.
  // heading_pitch_roll: objects only, body -> local north-east-down at the
  // object's place at each step (pushed in EOIR_FRAME_GEODETIC_NED).
  // velocity: body +z along the velocity in the motion's frame (motion.hpp velocity_attitude).
  enum class Type { none, fixed_inertial, nadir, target, spinning_inertial, azel, heading_pitch_roll, velocity };
  Type type = Type::none;
  Quat quaternion{1, 0, 0, 0};  // body -> J2000 (fixed_inertial; spinning_inertial at the epoch)
  std::string target;           // object name (target)
  Vec3 axis_body{0, 0, 1};      // spinning_inertial: the body axis it turns about
  double rate_deg_s = 0;        //   and how fast
  double epoch_s = 0;           //   when it has `quaternion` (default: the scenario's start)
  double azimuth_deg = 0;       // azel: from north through east
  double elevation_deg = 0;     //   above the geodetic horizon
  double heading_deg = 0;       // heading_pitch_roll: from north through east
  double pitch_deg = 0;         //   nose up
  double roll_deg = 0;          //   right wing down
};

// Where the host pushes an object's state from.
struct Motion {
  enum class Kind { fixed_geodetic, kepler, ephemeris, tle, ballistic };
  Kind kind = Kind::fixed_geodetic;
  double lat_deg = 0, lon_deg = 0, alt_m = 0;  // fixed_geodetic
  std::shared_ptr<const KeplerOrbit> kepler;   // kepler (J2000)
  std::shared_ptr<const Ephemeris> ephemeris;  // ephemeris
  bool earth_fixed = false;                    // ephemeris frame
  std::shared_ptr<const Sgp4> tle;             // tle (SGP4 in TEME, pushed in J2000)
  std::shared_ptr<const BallisticArc> ballistic;  // ballistic (Earth-fixed)
};

struct ObjectSpec {
  std::string name;  // objects of a tle_file: the set's title line
  std::string kind;  // satellite, aircraft, ground_vehicle, missile, site (fixed_geodetic motion only)
  Motion motion;
  Attitude attitude;
  nlohmann::json properties = nlohmann::json::object();
  std::string path;  // "objects[i]"; objects of a tle_file: "objects[i].tle_file line N" (N: the title's)
};

struct SensorSpec {
  std::string name, parent;
  Attitude pointing;
  nlohmann::json parameters = nlohmann::json::object();
  std::string path;  // "sensors[i]"
};

// Properties of a central body (central_bodies[i] given as an object).
struct BodyProperties {
  std::string name;
  nlohmann::json properties = nlohmann::json::object();
  std::string path;  // "central_bodies[i]"
};

// The engine's object limits a scenario asks for (eoir_engine_set_limits);
// 0: the default profile's value.
struct ScenarioLimits {
  std::uint32_t max_satellites = 0, max_vehicles = 0, max_sites = 0, max_missiles = 0, max_sensors = 0;
  bool given = false;
};

struct Scenario {
  std::string file;
  ScenarioLimits limits;
  std::string name, description;
  double start_s = 0, stop_s = 0, step_s = 60;
  std::vector<std::string> central_bodies;   // added in this order (never the Sun, always present)
  std::vector<BodyProperties> body_properties;  // applied after the bodies are added (may name the Sun)
  bool stars = false;
  std::vector<ObjectSpec> objects;
  std::vector<SensorSpec> sensors;

  const ObjectSpec* find_object(const std::string& name) const;
  const SensorSpec* find_sensor(const std::string& name) const;
};

// Files a scenario names (properties ending in _file: the star field's
// catalog_file) are relative to the scenario's folder and must lie inside
// it, `..` and symbolic links resolved, whether they exist or not (README
// "Bounds"); a path outside is refused before it is opened, naming the
// field, unless allow_paths_outside (eoir --allow-paths-outside).
struct ScenarioOptions {
  bool allow_paths_outside = false;
};

// Reads and checks a scenario file. Throws ScenarioError ("FILE: PATH: why").
Scenario load_scenario(const std::string& file, const ScenarioOptions& options = {});
// Checks a parsed JSON document (file locates the files it names, and names
// it in messages).
Scenario parse_scenario(const nlohmann::json& doc, const std::string& file, const ScenarioOptions& options = {});

// The object's position and velocity at t in its own frame (J2000 for kepler,
// tle and j2000 ephemerides, Earth-fixed for earth_fixed ephemerides and
// ballistic flights, geodetic
// {lat, lon, height} for fixed_geodetic). Throws ScenarioError naming
// "objects[i].motion" (e.g. a time outside the ephemeris).
PosVel motion_state(const ObjectSpec& object, double t_s);

// SGP4 from two-line elements at host time t (seconds, iso_time.hpp), rotated
// from TEME into J2000 (sgp4.hpp). Throws Sgp4Error.
PosVel tle_state_j2000(const Sgp4& sgp4, double t_s);

}  // namespace eoir::cli
