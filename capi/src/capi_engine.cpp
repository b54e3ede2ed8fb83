// Engine lifetime, time, object registration and states.
#include <cstddef>
#include <cstring>

#include "capi_internal.hpp"
#include "universe/object_motion.hpp"
#include "universe/pointing.hpp"

using namespace eoir;
using eoir::capi::guarded;
using eoir::capi::need;
using eoir::capi::need_size;
using eoir::capi::str;
using eoir::capi::with_engine;

using eoir::capi::scale_of;
using eoir::capi::time_of;

namespace eoir::capi {
TimeScale scale_of(int32_t s, const std::string& field) {
  if (s < EOIR_TIME_UTC || s > EOIR_TIME_TDB)
    throw Error(Status::out_of_range, field + ": unknown time scale " + std::to_string(s));
  return static_cast<TimeScale>(s);
}
EngineTime time_of(const eoir_time* t, const std::string& field) {
  need(t, field.c_str());
  return EngineTime::from(JulianDate{scale_of(t->scale, field + ".scale"), t->jd1, t->jd2}, field);
}
}  // namespace eoir::capi

extern "C" {

EOIR_API eoir_status eoir_engine_create(const eoir_engine_desc* desc, eoir_engine* engine_out) {
  return guarded([&] {
    need(engine_out, "engine_out");
    *engine_out = nullptr;
    EngineOptions options;
    if (desc) {
      need_size(desc->struct_size, offsetof(eoir_engine_desc, data_dir), "desc");
      if (desc->threads > 1024)
        throw Error(Status::out_of_range, "desc.threads: at most 1024 worker threads, got " +
                                              std::to_string(desc->threads));
      options.threads = desc->threads;
      options.seed = desc->seed;
      if (desc->struct_size >= offsetof(eoir_engine_desc, data_dir) + sizeof desc->data_dir && desc->data_dir)
        options.data_dir = desc->data_dir;
    }
    capi::attach_host_services(options);
    auto handle = std::make_unique<eoir_engine_s>();
    handle->engine = std::make_unique<Engine>(options);
    *engine_out = handle.release();
  });
}

EOIR_API void eoir_engine_destroy(eoir_engine engine) { delete engine; }

EOIR_API eoir_status eoir_engine_set_limits(eoir_engine engine, const eoir_limits* limits) {
  return with_engine(engine, [&](Engine& e) {
    need(limits, "limits");
    need_size(limits->struct_size, sizeof(eoir_limits), "limits");
    universe::ObjectLimits l;
    l.satellites = limits->max_satellites;
    l.vehicles = limits->max_vehicles;
    l.sites = limits->max_sites;
    l.missiles = limits->max_missiles;
    l.sensors = limits->max_sensors;
    e.set_limits(l);
  });
}

EOIR_API eoir_status eoir_engine_get_limits(eoir_engine engine, eoir_limits* limits_out) {
  return with_engine(engine, [&](Engine& e) {
    need(limits_out, "limits_out");
    need_size(limits_out->struct_size, sizeof(eoir_limits), "limits_out");
    const universe::ObjectLimits& l = e.universe().limits();
    limits_out->max_satellites = static_cast<uint32_t>(l.satellites);
    limits_out->max_vehicles = static_cast<uint32_t>(l.vehicles);
    limits_out->max_sites = static_cast<uint32_t>(l.sites);
    limits_out->max_missiles = static_cast<uint32_t>(l.missiles);
    limits_out->max_sensors = static_cast<uint32_t>(l.sensors);
  });
}

EOIR_API eoir_status eoir_engine_set_time(eoir_engine engine, const eoir_time* time) {
  return with_engine(engine, [&](Engine& e) { e.set_time(time_of(time, "time")); });
}

EOIR_API eoir_status eoir_engine_get_time(eoir_engine engine, int32_t scale, eoir_time* time_out) {
  return with_engine(engine, [&](Engine& e) {
    need(time_out, "time_out");
    const JulianDate d = e.time().to(scale_of(scale, "scale"));
    time_out->scale = scale;
    time_out->jd1 = d.jd1;
    time_out->jd2 = d.jd2;
  });
}

EOIR_API eoir_status eoir_time_from_iso(const char* iso_utc, eoir_time* time_out) {
  return guarded([&] {
    const std::string iso = str(iso_utc, "iso_utc");
    need(time_out, "time_out");
    const JulianDate d = utc_from_iso(iso);
    time_out->scale = EOIR_TIME_UTC;
    time_out->jd1 = d.jd1;
    time_out->jd2 = d.jd2;
  });
}

EOIR_API eoir_status eoir_time_to_iso(const eoir_time* time, char* buffer, size_t capacity) {
  return guarded([&] {
    need(buffer, "buffer");
    const EngineTime t = time_of(time, "time");
    const std::string iso = iso_from_utc(t.to(TimeScale::utc), 3);
    if (iso.size() + 1 > capacity)
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(iso.size() + 1) + " bytes needed");
    std::memcpy(buffer, iso.c_str(), iso.size() + 1);
  });
}

EOIR_API eoir_status eoir_object_add(eoir_engine engine, int32_t kind, const char* name) {
  return with_engine(engine, [&](Engine& e) {
    const std::string n = str(name, "name");
    if ((kind < EOIR_KIND_CENTRAL_BODY || kind > EOIR_KIND_MISSILE) && kind != EOIR_KIND_SITE) {
      if (kind == EOIR_KIND_SENSOR)
        throw Error(Status::out_of_range, "kind: add sensors with eoir_sensor_add (they need a parent)");
      throw Error(Status::out_of_range, "kind: unknown object kind " + std::to_string(kind));
    }
    e.add_object(static_cast<universe::ObjectKind>(kind), n);
  });
}

EOIR_API eoir_status eoir_sensor_add(eoir_engine engine, const char* name, const char* parent) {
  return with_engine(engine, [&](Engine& e) { e.add_sensor(str(name, "name"), str(parent, "parent")); });
}

EOIR_API eoir_status eoir_object_remove(eoir_engine engine, const char* name) {
  return with_engine(engine, [&](Engine& e) { e.remove_object(str(name, "name")); });
}

EOIR_API eoir_status eoir_object_count(eoir_engine engine, size_t* count_out) {
  return with_engine(engine, [&](Engine& e) {
    need(count_out, "count_out");
    *count_out = e.universe().objects().size();
  });
}

EOIR_API eoir_status eoir_object_at(eoir_engine engine, size_t index, const char** name_out, int32_t* kind_out) {
  return with_engine(engine, [&](Engine& e) {
    need(name_out, "name_out");
    const auto& objects = e.universe().objects();
    if (index >= objects.size())
      throw Error(Status::out_of_range, "index: " + std::to_string(index) + " >= object count " +
                                            std::to_string(objects.size()));
    // The name lives as long as the object (until it is removed or the state
    // is restored).
    *name_out = objects[index].name.c_str();
    if (kind_out) *kind_out = static_cast<int32_t>(objects[index].kind);
  });
}

EOIR_API eoir_status eoir_object_set_state(eoir_engine engine, const char* name, const eoir_time* time,
                                           const eoir_state* state) {
  return with_engine(engine, [&](Engine& e) {
    const std::string n = str(name, "name");
    need(state, "state");
    constexpr size_t v12_size = offsetof(eoir_state, angular_velocity);  // before 1.3 appended it
    need_size(state->struct_size, v12_size, "state");
    const bool has_rate = state->struct_size >= offsetof(eoir_state, angular_velocity) + sizeof state->angular_velocity;
    const EngineTime epoch = time ? time_of(time, "time") : e.time();
    e.push_state(n, epoch, state->frame, state->position, state->velocity, state->attitude,
                 has_rate ? state->angular_velocity : nullptr);
  });
}

EOIR_API eoir_status eoir_object_get_state(eoir_engine engine, const char* name, eoir_state* state) {
  return with_engine(engine, [&](Engine& e) {
    const universe::Object& o = e.universe().get(str(name, "name"));
    need(state, "state");
    need_size(state->struct_size, offsetof(eoir_state, angular_velocity), "state");
    const bool has_rate = state->struct_size >= offsetof(eoir_state, angular_velocity) + sizeof state->angular_velocity;
    const universe::Kinematics k = universe::kinematics_at(e.universe(), o, e.time());
    frames::Vec3 r = k.position_m, v = k.velocity_m_s;
    Eigen::Quaterniond q = k.attitude;
    frames::Mat3 to_ned = frames::Mat3::Identity();  // Earth-fixed -> the asked axes
    if (state->frame == EOIR_FRAME_EARTH_FIXED || state->frame == EOIR_FRAME_GEODETIC ||
        state->frame == EOIR_FRAME_GEODETIC_NED) {
      frames::j2000_to_earth_fixed(e.time(), k.position_m, k.velocity_m_s, r, v);
      q = Eigen::Quaterniond(frames::j2000_to_earth_fixed(e.time())) * k.attitude;
      if (state->frame != EOIR_FRAME_EARTH_FIXED) r = frames::earth_fixed_to_geodetic(r);
      if (state->frame == EOIR_FRAME_GEODETIC_NED) {
        to_ned = frames::ned_to_earth_fixed(r.x(), r.y()).transpose();
        v = to_ned * v;
        q = Eigen::Quaterniond(to_ned) * q;
      }
    } else if (state->frame != EOIR_FRAME_J2000) {
      throw Error(Status::out_of_range, "state.frame: unknown frame " + std::to_string(state->frame));
    }
    for (int i = 0; i < 3; ++i) {
      state->position[i] = r[i];
      state->velocity[i] = v[i];
    }
    state->attitude[0] = q.w();
    state->attitude[1] = q.x();
    state->attitude[2] = q.y();
    state->attitude[3] = q.z();
    if (has_rate) {
      // The pushed angular velocity (the object's, or a sensor's own), in the
      // frame asked for (central bodies and objects without one: zero).
      // A site's attitude is fixed in the Earth-fixed frame.
      const universe::Object* carrier = &o;
      if (o.kind == universe::ObjectKind::sensor && !o.state.valid) carrier = &e.universe().get(o.parent);
      frames::Vec3 w = carrier->state.valid ? carrier->state.angular_velocity_rad_s : frames::Vec3::Zero();
      const bool pushed_j2000 = carrier->state.valid ? carrier->state.frame == universe::StateFrame::j2000
                                                     : carrier->kind != universe::ObjectKind::site;
      const bool want_j2000 = state->frame == EOIR_FRAME_J2000;
      // The Earth-fixed frame itself turns at the Earth's rate about its z.
      const frames::Vec3 earth_rate(0.0, 0.0, 7.292115e-5);
      if (pushed_j2000 && !want_j2000) w = frames::j2000_to_earth_fixed(e.time()) * w - earth_rate;
      if (!pushed_j2000 && want_j2000) w = frames::j2000_to_earth_fixed(e.time()).transpose() * (w + earth_rate);
      if (!want_j2000) w = to_ned * w;
      for (int i = 0; i < 3; ++i) state->angular_velocity[i] = w[i];
    }
  });
}

namespace {
// Pushes a sensor's attitude as computed by universe/pointing.hpp.
void push_sensor_attitude(Engine& e, const std::string& sensor, const universe::PushedState& s) {
  const double zero[3] = {0, 0, 0};
  const double q[4] = {s.attitude.w(), s.attitude.x(), s.attitude.y(), s.attitude.z()};
  const double w[3] = {s.angular_velocity_rad_s.x(), s.angular_velocity_rad_s.y(), s.angular_velocity_rad_s.z()};
  e.push_state(sensor, s.epoch, s.frame == universe::StateFrame::j2000 ? EOIR_FRAME_J2000 : EOIR_FRAME_EARTH_FIXED,
               zero, zero, q, w);
}
}  // namespace

EOIR_API eoir_status eoir_sensor_point_azel(eoir_engine engine, const char* sensor, double azimuth_deg,
                                            double elevation_deg) {
  return with_engine(engine, [&](Engine& e) {
    const universe::Object& s = e.universe().sensor(str(sensor, "sensor"));
    push_sensor_attitude(e, s.name,
                         universe::azimuth_elevation_pointing(e.universe(), s, e.time(), azimuth_deg, elevation_deg));
  });
}

EOIR_API eoir_status eoir_sensor_point_at(eoir_engine engine, const char* sensor, const char* target) {
  return with_engine(engine, [&](Engine& e) {
    const universe::Object& s = e.universe().sensor(str(sensor, "sensor"));
    const std::string t = str(target, "target");
    push_sensor_attitude(e, s.name, universe::target_pointing(e.universe(), s, t, e.time()));
  });
}
}
