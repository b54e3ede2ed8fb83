// libeoir_host: the CLI's scenario, motion and session code behind a C
// interface (eoir_host.h). No second implementation: this file only
// translates between C and plugin_host/cli.
#include "eoir_host.h"

#include <cmath>
#include <cstring>
#include <optional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine.hpp"
#include "iso_time.hpp"
#include "run.hpp"
#include "scenario.hpp"
#include "session.hpp"
#include "sgp4.hpp"
#include "time_steps.hpp"

using namespace eoir::cli;

struct eoir_host_session_s {
  std::unique_ptr<Engine> engine;
  Scenario scenario;
  std::unique_ptr<Session> session;
};

namespace {

thread_local std::string g_error;

eoir_status fail(eoir_status status, const std::string& message) {
  g_error = message;
  return status;
}

// Runs f, translating the CLI's exceptions into a status and a message.
template <class F>
eoir_status guarded(F&& f) {
  try {
    g_error.clear();
    return f();
  } catch (const EngineError& e) {
    return fail(e.status(), e.what());
  } catch (const ScenarioError& e) {
    return fail(EOIR_ERR_CORRUPT_FILE, e.what());
  } catch (const Sgp4Error& e) {
    return fail(EOIR_ERR_OUT_OF_RANGE, std::string("SGP4: ") + e.what());
  } catch (const std::invalid_argument& e) {
    return fail(EOIR_ERR_OUT_OF_RANGE, e.what());
  } catch (const std::bad_alloc&) {
    return fail(EOIR_ERR_INTERNAL, "out of memory");
  } catch (const std::exception& e) {
    return fail(EOIR_ERR_INTERNAL, e.what());
  } catch (...) {
    return fail(EOIR_ERR_INTERNAL, "unknown exception");
  }
}

eoir_status copy_out(const std::string& text, char* buffer, size_t capacity, size_t* needed) {
  if (needed != nullptr) *needed = text.size() + 1;
  if (buffer == nullptr || capacity < text.size() + 1)
    return fail(EOIR_ERR_BUFFER_TOO_SMALL, "buffer: " + std::to_string(text.size() + 1) + " bytes needed");
  std::memcpy(buffer, text.c_str(), text.size() + 1);
  return EOIR_OK;
}

eoir_status need(const void* p, const char* what) {
  if (p == nullptr) return fail(EOIR_ERR_NULL_ARGUMENT, std::string(what) + ": is NULL");
  return EOIR_OK;
}

const char* motion_name(Motion::Kind k) {
  switch (k) {
    case Motion::Kind::fixed_geodetic: return "fixed_geodetic";
    case Motion::Kind::kepler: return "kepler";
    case Motion::Kind::ephemeris: return "ephemeris";
    case Motion::Kind::tle: return "tle";
    case Motion::Kind::ballistic: return "ballistic";
  }
  return "?";
}

double parse_time(const char* iso, const char* what) {
  try {
    return parse_iso(iso);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(what) + ": " + e.what());
  }
}

}  // namespace

extern "C" {

EOIR_API uint32_t eoir_host_version(void) { return EOIR_HOST_VERSION; }

EOIR_API const char* eoir_host_last_error(void) { return g_error.c_str(); }

EOIR_API eoir_status eoir_host_session_open(const char* library, const char* scenario_file, uint64_t seed,
                                            uint32_t threads, eoir_host_session* session_out) {
  return eoir_host_session_open_with(library, scenario_file, seed, threads, 0, session_out);
}

EOIR_API eoir_status eoir_host_session_open_with(const char* library, const char* scenario_file, uint64_t seed,
                                                 uint32_t threads, uint32_t options,
                                                 eoir_host_session* session_out) {
  if (need(scenario_file, "scenario_file") || need(session_out, "session_out")) return EOIR_ERR_NULL_ARGUMENT;
  *session_out = nullptr;
  if ((options & ~EOIR_HOST_ALLOW_PATHS_OUTSIDE) != 0)
    return fail(EOIR_ERR_OUT_OF_RANGE,
                "options: unknown bits " + std::to_string(options & ~EOIR_HOST_ALLOW_PATHS_OUTSIDE));
  return guarded([&] {
    auto s = std::make_unique<eoir_host_session_s>();
    ScenarioOptions scenario_options;
    scenario_options.allow_paths_outside = (options & EOIR_HOST_ALLOW_PATHS_OUTSIDE) != 0;
    s->scenario = load_scenario(scenario_file, scenario_options);
    EngineConfig config;
    config.library = (library != nullptr && library[0] != '\0') ? library : nullptr;
    config.seed = seed;
    config.threads = threads;
    try {
      s->engine = std::make_unique<Engine>(config);
    } catch (const EngineError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw EngineError(e.what(), EOIR_ERR_IO);
    }
    s->session = std::make_unique<Session>(*s->engine, s->scenario);
    s->session->set_time(s->scenario.start_s);
    *session_out = s.release();
    return EOIR_OK;
  });
}

EOIR_API void eoir_host_session_close(eoir_host_session session) {
  if (session == nullptr) return;
  session->session.reset();
  session->engine.reset();
  delete session;
}

EOIR_API eoir_engine eoir_host_session_engine(eoir_host_session session) {
  return session != nullptr && session->engine ? session->engine->handle() : nullptr;
}

EOIR_API const char* eoir_host_session_library(eoir_host_session session) {
  return session != nullptr && session->engine ? session->engine->library_path() : "";
}

EOIR_API eoir_status eoir_host_session_describe(eoir_host_session session, char* buffer, size_t capacity,
                                                size_t* needed) {
  if (need(session, "session")) return EOIR_ERR_NULL_ARGUMENT;
  return guarded([&] {
    const Scenario& sc = session->scenario;
    nlohmann::ordered_json d;
    d["name"] = sc.name;
    d["description"] = sc.description;
    d["file"] = sc.file;
    d["start"] = format_iso(sc.start_s);
    d["stop"] = format_iso(sc.stop_s);
    d["step_s"] = sc.step_s;
    d["central_bodies"] = sc.central_bodies;
    d["objects"] = nlohmann::ordered_json::array();
    for (const auto& o : sc.objects)
      d["objects"].push_back({{"name", o.name}, {"kind", o.kind}, {"motion", motion_name(o.motion.kind)}});
    d["sensors"] = nlohmann::ordered_json::array();
    for (const auto& s : sc.sensors) d["sensors"].push_back({{"name", s.name}, {"parent", s.parent}});
    return copy_out(d.dump(), buffer, capacity, needed);
  });
}

EOIR_API eoir_status eoir_host_session_times(eoir_host_session session, const char* start, const char* stop,
                                             double step_s, char* buffer, size_t capacity, size_t* needed) {
  if (need(session, "session")) return EOIR_ERR_NULL_ARGUMENT;
  return guarded([&] {
    const Scenario& sc = session->scenario;
    std::optional<double> t0, t1;
    if (start != nullptr) t0 = parse_time(start, "start");
    if (stop != nullptr) t1 = parse_time(stop, "stop");
    if (!std::isfinite(step_s)) return fail(EOIR_ERR_OUT_OF_RANGE, "step_s: not finite");
    const std::vector<double> times =
        step_times(t0.value_or(sc.start_s), default_stop(t0, t1, sc), step_s > 0 ? step_s : sc.step_s, 1000000);
    nlohmann::json list = nlohmann::json::array();
    for (double t : times) list.push_back(format_iso(t));
    return copy_out(list.dump(), buffer, capacity, needed);
  });
}

EOIR_API eoir_status eoir_host_session_set_time(eoir_host_session session, const char* iso_utc) {
  if (need(session, "session") || need(iso_utc, "iso_utc")) return EOIR_ERR_NULL_ARGUMENT;
  return guarded([&] {
    session->session->set_time(parse_time(iso_utc, "time"));
    return EOIR_OK;
  });
}

EOIR_API eoir_status eoir_host_session_fits_header(eoir_host_session session, const char* sensor,
                                                   int32_t image_kind, int64_t frame_index, char* buffer,
                                                   size_t capacity, size_t* needed) {
  if (need(session, "session") || need(sensor, "sensor")) return EOIR_ERR_NULL_ARGUMENT;
  return guarded([&] {
    const SensorSpec* spec = session->scenario.find_sensor(sensor);
    if (spec == nullptr) return fail(EOIR_ERR_UNKNOWN_NAME, std::string("sensor: unknown sensor '") + sensor + "'");
    if (frame_index < 0) return fail(EOIR_ERR_OUT_OF_RANGE, "frame_index: must be >= 0");
    const eoir::imageio::FitsHeader h = frame_fits_header(*session->engine, session->scenario, *spec,
                                                          static_cast<std::size_t>(frame_index), image_kind);
    nlohmann::json cards = nlohmann::json::array();
    using Kind = eoir::imageio::FitsCard::Kind;
    for (const auto& c : h.cards()) {
      switch (c.kind) {
        case Kind::String: cards.push_back({c.key, c.text, c.comment}); break;
        case Kind::Double: cards.push_back({c.key, c.number, c.comment}); break;
        case Kind::Integer: cards.push_back({c.key, c.integer, c.comment}); break;
        case Kind::Logical: cards.push_back({c.key, c.logical, c.comment}); break;
        case Kind::Comment: cards.push_back({"COMMENT", c.text, ""}); break;
        case Kind::History: cards.push_back({"HISTORY", c.text, ""}); break;
      }
    }
    return copy_out(cards.dump(), buffer, capacity, needed);
  });
}

EOIR_API eoir_status eoir_host_session_truth(eoir_host_session session, const char* sensor, char* buffer,
                                             size_t capacity, size_t* needed) {
  if (need(session, "session") || need(sensor, "sensor")) return EOIR_ERR_NULL_ARGUMENT;
  return guarded([&] {
    if (session->scenario.find_sensor(sensor) == nullptr)
      return fail(EOIR_ERR_UNKNOWN_NAME, std::string("sensor: unknown sensor '") + sensor + "'");
    return copy_out(frame_truth_json(*session->engine, session->scenario, sensor), buffer, capacity, needed);
  });
}

EOIR_API eoir_status eoir_host_tle_state(const char* line1, const char* line2, const char* iso_utc,
                                         double teme_position_km[3], double teme_velocity_km_s[3],
                                         double j2000_position_m[3], double j2000_velocity_m_s[3]) {
  if (need(line1, "line1") || need(line2, "line2") || need(iso_utc, "iso_utc")) return EOIR_ERR_NULL_ARGUMENT;
  return guarded([&] {
    const Sgp4 sgp4 = Sgp4::from_tle(line1, line2);
    const double t = parse_time(iso_utc, "time");
    const double minutes = ((2451545.0 - sgp4.epoch_jd()) - sgp4.epoch_jd_fraction()) * 1440.0 + t / 60.0;
    const TemeState teme = sgp4.at_minutes(minutes);
    const PosVel j2000 = tle_state_j2000(sgp4, t);
    for (int k = 0; k < 3; ++k) {
      if (teme_position_km) teme_position_km[k] = teme.r_km[k];
      if (teme_velocity_km_s) teme_velocity_km_s[k] = teme.v_km_s[k];
      if (j2000_position_m) j2000_position_m[k] = j2000.position[k];
      if (j2000_velocity_m_s) j2000_velocity_m_s[k] = j2000.velocity[k];
    }
    return EOIR_OK;
  });
}

}  // extern "C"
