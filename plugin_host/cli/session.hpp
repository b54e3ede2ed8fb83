// A scenario loaded into an engine: objects, sensors and their properties are
// registered once; set_time() moves the engine clock and pushes every
// object's state (host-side motion, as STK drives EOIR).
#pragma once
#include <map>
#include <string>

#include "engine.hpp"
#include "scenario.hpp"

namespace eoir::cli {

class Session {
 public:
  // Registers everything; throws EngineError naming the JSON path, e.g.
  // "sensors[0].parameters.f_number: <engine message>".
  Session(Engine& engine, const Scenario& scenario);
  // Sets the engine time and pushes all states. Throws EngineError or
  // ScenarioError (e.g. a time outside an ephemeris).
  void set_time(double t_s);

  const Scenario& scenario() const { return scenario_; }
  Engine& engine() const { return engine_; }

 private:
  void apply_properties(const std::string& object, const nlohmann::json& props, const std::string& path);
  // Target pointing the engine does (eoir_sensor_point_at): from a site,
  // with the zenith up in the picture.
  bool engine_pointed_target(const SensorSpec& s) const;
  PosVel j2000_state(const std::string& name, const std::string& where);
  // The attitude (body -> J2000) at this step moved by dt_s seconds, the
  // states of self and a target extrapolated linearly.
  Quat attitude_j2000(const Attitude& a, const PosVel& self, const std::string& where, double dt_s = 0);
  // Its angular velocity (J2000 axes, rad/s): exact for spinning_inertial,
  // by central differences over +-0.5 s for nadir and target pointing.
  Vec3 angular_velocity_j2000(const Attitude& a, const PosVel& self, const std::string& where);
  void push(const std::string& name, int32_t frame, const PosVel& s, const Quat& q, const std::string& where,
            const Vec3& angular_velocity = {0, 0, 0});

  Engine& engine_;
  const Scenario& scenario_;
  double t_s_ = 0;
  std::map<std::string, PosVel> host_j2000_;  // this step's J2000 states computed by the host
};

}  // namespace eoir::cli
