#include "session.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

#include "iso_time.hpp"
#include "suggest.hpp"

namespace eoir::cli {
namespace {

int32_t kind_code(const std::string& kind) {
  if (kind == "satellite") return EOIR_KIND_SATELLITE;
  if (kind == "aircraft") return EOIR_KIND_AIRCRAFT;
  if (kind == "ground_vehicle") return EOIR_KIND_GROUND_VEHICLE;
  if (kind == "site") return EOIR_KIND_SITE;
  return EOIR_KIND_MISSILE;
}

// The engine's pointing calls (C ABI 1.5), or an error naming `where`.
void need_pointing(const eoir_api_v1& api, const std::string& where) {
  if (api.struct_size < offsetof(eoir_api_v1, sensor_point_at) + sizeof api.sensor_point_at ||
      api.sensor_point_azel == nullptr || api.sensor_point_at == nullptr)
    throw EngineError(where + ": the engine library cannot point sensors (C ABI 1.5 needed)", EOIR_ERR_ABI_MISMATCH);
}

bool natural_j2000(const ObjectSpec& o) {
  return o.motion.kind == Motion::Kind::kepler || o.motion.kind == Motion::Kind::tle ||
         (o.motion.kind == Motion::Kind::ephemeris && !o.motion.earth_fixed);
}

int32_t natural_frame(const ObjectSpec& o) {
  if (o.motion.kind == Motion::Kind::fixed_geodetic) return EOIR_FRAME_GEODETIC;
  return natural_j2000(o) ? EOIR_FRAME_J2000 : EOIR_FRAME_EARTH_FIXED;
}

}  // namespace

Session::Session(Engine& engine, const Scenario& sc) : engine_(engine), scenario_(sc) {
  const eoir_api_v1& api = engine_.api();
  const eoir_engine e = engine_.handle();
  if (sc.limits.given) {
    if (api.struct_size < offsetof(eoir_api_v1, engine_get_limits) + sizeof api.engine_get_limits ||
        api.engine_set_limits == nullptr || api.engine_get_limits == nullptr)
      throw EngineError("limits: the engine library cannot set object limits (C ABI 1.7 needed)", EOIR_ERR_ABI_MISMATCH);
    eoir_limits l{};
    l.struct_size = sizeof l;
    engine_.check(api.engine_get_limits(e, &l), "limits");
    const auto take = [](std::uint32_t asked, std::uint32_t& limit) {
      if (asked > 0) limit = asked;
    };
    take(sc.limits.max_satellites, l.max_satellites);
    take(sc.limits.max_vehicles, l.max_vehicles);
    take(sc.limits.max_sites, l.max_sites);
    take(sc.limits.max_missiles, l.max_missiles);
    take(sc.limits.max_sensors, l.max_sensors);
    engine_.check(api.engine_set_limits(e, &l), "limits");
  }
  for (std::size_t i = 0; i < sc.central_bodies.size(); ++i)
    engine_.check(api.object_add(e, EOIR_KIND_CENTRAL_BODY, sc.central_bodies[i].c_str()),
                  "central_bodies[" + std::to_string(i) + "]");
  if (sc.stars) engine_.check(api.object_add(e, EOIR_KIND_STAR_FIELD, "Stars"), "stars");
  for (const auto& b : sc.body_properties) apply_properties(b.name, b.properties, b.path + ".properties");
  for (const auto& o : sc.objects) {
    engine_.check(api.object_add(e, kind_code(o.kind), o.name.c_str()), o.path + ".name");
    if (o.kind == "site") {
      // A site is placed once, by its properties; it takes no states.
      const Motion& m = o.motion;
      engine_.check(api.set_number(e, o.name.c_str(), "latitude_deg", m.lat_deg), o.path + ".motion.lat_deg");
      engine_.check(api.set_number(e, o.name.c_str(), "longitude_deg", m.lon_deg), o.path + ".motion.lon_deg");
      engine_.check(api.set_number(e, o.name.c_str(), "height_m", m.alt_m), o.path + ".motion.alt_m");
    }
    apply_properties(o.name, o.properties, o.path + ".properties");
  }
  for (const auto& s : sc.sensors) {
    engine_.check(api.sensor_add(e, s.name.c_str(), s.parent.c_str()), s.path);
    apply_properties(s.name, s.parameters, s.path + ".parameters");
    if (s.pointing.type == Attitude::Type::azel || engine_pointed_target(s)) need_pointing(api, s.path + ".pointing");
  }
}

bool Session::engine_pointed_target(const SensorSpec& s) const {
  const ObjectSpec* parent = scenario_.find_object(s.parent);
  return s.pointing.type == Attitude::Type::target && parent && parent->kind == "site";
}

void Session::apply_properties(const std::string& object, const nlohmann::json& props, const std::string& path) {
  const eoir_api_v1& api = engine_.api();
  const eoir_engine e = engine_.handle();
  // The declared types, to tell integers from numbers, and the engine's
  // table order, in which every property may be set (shape before
  // dimensions_m): keys are applied in that order, unknown keys last.
  std::map<std::string, int32_t> types;
  std::vector<std::string> order;
  for (const PropertyInfo& p : engine_.properties(object)) {
    types[p.name] = p.type;
    if (props.contains(p.name)) order.push_back(p.name);
  }
  for (auto it = props.begin(); it != props.end(); ++it)
    if (types.count(it.key()) == 0) order.push_back(it.key());
  for (const std::string& key : order) {
    const std::string where = path + "." + key;
    const nlohmann::json& v = props.at(key);
    const auto t = types.find(key);
    const int32_t declared = t == types.end() ? 0 : t->second;
    eoir_status s;
    if (v.is_boolean()) {
      s = api.set_bool(e, object.c_str(), key.c_str(), v.get<bool>() ? 1 : 0);
    } else if (v.is_number()) {
      const double x = v.get<double>();
      if (declared == EOIR_TYPE_INTEGER) {
        if (!(std::isfinite(x) && x == std::floor(x) && std::fabs(x) < 9.0e15))
          throw EngineError(where + ": must be an integer, not " + v.dump(), EOIR_ERR_TYPE_MISMATCH);
        s = api.set_integer(e, object.c_str(), key.c_str(), static_cast<int64_t>(x));
      } else {
        s = api.set_number(e, object.c_str(), key.c_str(), x);
      }
    } else if (v.is_string()) {
      s = api.set_string(e, object.c_str(), key.c_str(), v.get<std::string>().c_str());
    } else if (v.is_array()) {
      // A flat array of numbers; nested arrays (pairs) are flattened in order.
      std::vector<double> values;
      for (std::size_t i = 0; i < v.size(); ++i) {
        const auto add_number = [&](const nlohmann::json& x, const std::string& p) {
          if (!x.is_number()) throw EngineError(p + ": must be a number, not " + x.dump(), EOIR_ERR_TYPE_MISMATCH);
          values.push_back(x.get<double>());
        };
        const std::string p = where + "[" + std::to_string(i) + "]";
        if (v[i].is_array())
          for (std::size_t k = 0; k < v[i].size(); ++k) add_number(v[i][k], p + "[" + std::to_string(k) + "]");
        else
          add_number(v[i], p);
      }
      s = api.set_array(e, object.c_str(), key.c_str(), values.data(), values.size());
    } else {
      throw EngineError(where + ": unsupported value type " + std::string(v.type_name()) +
                            " (use a number, string, bool or array of numbers)",
                        EOIR_ERR_TYPE_MISMATCH);
    }
    if (s == EOIR_ERR_UNKNOWN_NAME && t == types.end()) {
      std::vector<std::string> names;
      for (const auto& kv : types) names.push_back(kv.first);
      const std::string hint = did_you_mean(key, names);
      if (!hint.empty()) {
        const std::string why = api.last_error();
        throw EngineError(where + ": " + why + hint + " (EOIR_ERR_UNKNOWN_NAME)", s);
      }
    }
    engine_.check(s, where);
  }
}

void Session::push(const std::string& name, int32_t frame, const PosVel& st, const Quat& q, const std::string& where,
                   const Vec3& angular_velocity) {
  eoir_state s{};
  s.struct_size = sizeof s;
  s.frame = frame;
  for (int k = 0; k < 3; ++k) {
    s.position[k] = st.position[k];
    s.velocity[k] = st.velocity[k];
    s.angular_velocity[k] = angular_velocity[k];
  }
  for (int k = 0; k < 4; ++k) s.attitude[k] = q[k];
  engine_.check(engine_.api().object_set_state(engine_.handle(), name.c_str(), nullptr, &s), where);
}

PosVel Session::j2000_state(const std::string& name, const std::string& where) {
  const auto it = host_j2000_.find(name);
  if (it != host_j2000_.end()) return it->second;
  eoir_state s{};
  s.struct_size = sizeof s;
  s.frame = EOIR_FRAME_J2000;
  engine_.check(engine_.api().object_get_state(engine_.handle(), name.c_str(), &s), where);
  PosVel out;
  for (int k = 0; k < 3; ++k) {
    out.position[k] = s.position[k];
    out.velocity[k] = s.velocity[k];
  }
  host_j2000_[name] = out;
  return out;
}

Quat Session::attitude_j2000(const Attitude& a, const PosVel& self_now, const std::string& where, double dt_s) {
  PosVel self = self_now;
  self.position = add(self.position, scale(self.velocity, dt_s));
  try {
    switch (a.type) {
      case Attitude::Type::none:
      case Attitude::Type::azel:                // pointed by the engine (set_time step 3)
      case Attitude::Type::heading_pitch_roll:  // pushed in the local axes (set_time step 2)
        return {1, 0, 0, 0};
      case Attitude::Type::fixed_inertial:
        return a.quaternion;
      case Attitude::Type::spinning_inertial: {
        const double epoch = std::isnan(a.epoch_s) ? scenario_.start_s : a.epoch_s;
        const double angle = a.rate_deg_s * (t_s_ + dt_s - epoch) * (3.14159265358979323846 / 180.0);
        return normalize(multiply(a.quaternion, axis_angle(a.axis_body, angle)));
      }
      case Attitude::Type::nadir:
        return nadir_attitude(self);
      case Attitude::Type::velocity:
        return velocity_attitude(self);
      case Attitude::Type::target: {
        PosVel target = j2000_state(a.target, where + ".target");
        target.position = add(target.position, scale(target.velocity, dt_s));
        return point_z_axis(sub(target.position, self.position), self.velocity);
      }
    }
  } catch (const std::domain_error& e) {
    throw ScenarioError(where + ": " + e.what() + " at " + format_iso(t_s_));
  }
  return {1, 0, 0, 0};
}

Vec3 Session::angular_velocity_j2000(const Attitude& a, const PosVel& self, const std::string& where) {
  switch (a.type) {
    case Attitude::Type::none:
    case Attitude::Type::fixed_inertial:
      return {0, 0, 0};
    case Attitude::Type::spinning_inertial:
      return scale(rotate(attitude_j2000(a, self, where), a.axis_body), a.rate_deg_s * (3.14159265358979323846 / 180.0));
    default: {
      constexpr double h = 0.5;  // s
      return angular_velocity(attitude_j2000(a, self, where, -h), attitude_j2000(a, self, where, h), 2 * h);
    }
  }
}

void Session::set_time(double t) {
  t_s_ = t;
  const eoir_api_v1& api = engine_.api();
  const std::string iso = format_iso(t);
  eoir_time time{};
  engine_.check(api.time_from_iso(iso.c_str(), &time), "time " + iso);
  engine_.check(api.engine_set_time(engine_.handle(), &time), "time " + iso);
  host_j2000_.clear();

  // 1. Positions. Objects moving in J2000 get their final attitude now unless
  //    it depends on another object; the others are revisited in step 2.
  std::vector<const ObjectSpec*> later;
  for (const auto& o : scenario_.objects) {
    if (o.kind == "site") continue;  // fixed by its properties
    const PosVel st = motion_state(o, t);
    const bool j2000 = natural_j2000(o);
    if (j2000) host_j2000_[o.name] = st;
    if (o.attitude.type == Attitude::Type::velocity) {  // in the motion's own frame, final now
      push(o.name, natural_frame(o), st, velocity_attitude(st), o.path + ".motion", Vec3{0, 0, 0});
      continue;
    }
    const bool final_now = o.attitude.type == Attitude::Type::none ||
                           (j2000 && o.attitude.type != Attitude::Type::target &&
                            o.attitude.type != Attitude::Type::heading_pitch_roll);
    const bool turning = final_now && j2000;
    const Quat q = turning ? attitude_j2000(o.attitude, st, o.path + ".attitude") : Quat{1, 0, 0, 0};
    const Vec3 w = turning ? angular_velocity_j2000(o.attitude, st, o.path + ".attitude") : Vec3{0, 0, 0};
    push(o.name, natural_frame(o), st, q, o.path + ".motion", w);
    if (!final_now) later.push_back(&o);
  }
  // 2. Attitudes that need other objects' positions or a frame change: the
  //    state is re-pushed in J2000 (position from the engine if need be).
  for (const ObjectSpec* o : later) {
    if (o->attitude.type == Attitude::Type::heading_pitch_roll) {
      // Body -> local north-east-down at the object's place now.
      eoir_state g{};
      g.struct_size = sizeof g;
      g.frame = EOIR_FRAME_GEODETIC_NED;
      engine_.check(api.object_get_state(engine_.handle(), o->name.c_str(), &g), o->path + ".motion");
      PosVel local;
      for (int k = 0; k < 3; ++k) {
        local.position[k] = g.position[k];
        local.velocity[k] = g.velocity[k];
      }
      const Attitude& a = o->attitude;
      push(o->name, EOIR_FRAME_GEODETIC_NED, local, heading_pitch_roll(a.heading_deg, a.pitch_deg, a.roll_deg),
           o->path + ".attitude");
      continue;
    }
    const PosVel self = j2000_state(o->name, o->path + ".motion");
    push(o->name, EOIR_FRAME_J2000, self, attitude_j2000(o->attitude, self, o->path + ".attitude"),
         o->path + ".attitude", angular_velocity_j2000(o->attitude, self, o->path + ".attitude"));
  }
  // 3. Sensor pointing (position is the parent's; the engine ignores it).
  //    By azimuth and elevation, and tracking from a site, the engine
  //    computes the attitude and its rates itself.
  for (const auto& s : scenario_.sensors) {
    if (s.pointing.type == Attitude::Type::none) continue;
    if (s.pointing.type == Attitude::Type::azel) {
      engine_.check(api.sensor_point_azel(engine_.handle(), s.name.c_str(), s.pointing.azimuth_deg,
                                          s.pointing.elevation_deg),
                    s.path + ".pointing");
      continue;
    }
    if (engine_pointed_target(s)) {
      engine_.check(api.sensor_point_at(engine_.handle(), s.name.c_str(), s.pointing.target.c_str()),
                    s.path + ".pointing.target");
      continue;
    }
    const PosVel parent = j2000_state(s.parent, s.path + ".parent");
    push(s.name, EOIR_FRAME_J2000, parent, attitude_j2000(s.pointing, parent, s.path + ".pointing"),
         s.path + ".pointing", angular_velocity_j2000(s.pointing, parent, s.path + ".pointing"));
  }
}

}  // namespace eoir::cli
