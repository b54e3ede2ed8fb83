#include "engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace eoir::cli {
namespace {

void host_log(void* user, int32_t level, const char* message) {
  const bool verbose = *static_cast<const bool*>(user);
  if (level < 2 && !verbose) return;
  static const char* const names[] = {"debug", "info", "warning", "error"};
  std::fprintf(stderr, "eoir: engine %s: %s\n", (level >= 0 && level <= 3) ? names[level] : "log", message);
}

}  // namespace

Engine::Engine(const char* library, bool verbose) : Engine(EngineConfig{library, 1, 0}, verbose) {}

Engine::Engine(const EngineConfig& config, bool verbose) : verbose_(verbose) {
  const char* library = config.library;
  host_.struct_size = sizeof host_;
  host_.user = &verbose_;
  host_.log = host_log;
  host_.progress = nullptr;
  char message[EOIR_LOADER_MESSAGE_MAX];
  if (eoir_loader_open(library, EOIR_VERSION_MAJOR, &host_, &plugin_, message, sizeof message) != EOIR_OK)
    throw std::runtime_error(message);
  eoir_engine_desc desc{};
  desc.struct_size = sizeof desc;
  desc.threads = config.threads;
  desc.seed = config.seed;
  const eoir_status s = plugin_.api->engine_create(&desc, &engine_);
  if (s != EOIR_OK) {
    const std::string why = plugin_.api->last_error();
    eoir_loader_close(&plugin_);
    throw std::runtime_error("cannot create an engine: " + why);
  }
}

Engine::~Engine() {
  if (plugin_.api != nullptr) plugin_.api->engine_destroy(engine_);
  eoir_loader_close(&plugin_);
}

void Engine::check(eoir_status status, const std::string& where) const {
  if (status == EOIR_OK) return;
  std::string msg = where + ": " + api().last_error();
  const std::string name = api().status_name(status);
  if (msg.find(name) == std::string::npos) msg += " (" + name + ")";
  throw EngineError(msg, status);
}

}  // namespace eoir::cli

namespace eoir::cli {
// The current value of a property as JSON.
nlohmann::ordered_json Engine::value(const std::string& object, const std::string& name, int32_t type) const {
  const eoir_api_v1& a = api();
  const eoir_engine e = engine_;
  const std::string where = object + "." + name;
  switch (type) {
    case EOIR_TYPE_NUMBER: {
      double v = 0;
      check(a.get_number(e, object.c_str(), name.c_str(), &v), where);
      return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
    }
    case EOIR_TYPE_INTEGER: {
      int64_t v = 0;
      check(a.get_integer(e, object.c_str(), name.c_str(), &v), where);
      return v;
    }
    case EOIR_TYPE_BOOL: {
      int32_t v = 0;
      check(a.get_bool(e, object.c_str(), name.c_str(), &v), where);
      return v != 0;
    }
    case EOIR_TYPE_STRING: {
      std::vector<char> buf(256);
      for (;;) {
        const eoir_status st = a.get_string(e, object.c_str(), name.c_str(), buf.data(), buf.size());
        if (st == EOIR_ERR_BUFFER_TOO_SMALL && buf.size() < (std::size_t{1} << 26)) {
          buf.resize(buf.size() * 4);
          continue;
        }
        check(st, where);
        return std::string(buf.data());
      }
    }
    case EOIR_TYPE_ARRAY: {
      std::size_t n = 0;
      check(a.get_array(e, object.c_str(), name.c_str(), nullptr, 0, &n), where);
      std::vector<double> v(n);
      check(a.get_array(e, object.c_str(), name.c_str(), v.data(), v.size(), &n), where);
      return v;
    }
    default:
      return nullptr;
  }
}

std::vector<PropertyInfo> Engine::properties(const std::string& object) const {
  std::vector<PropertyInfo> out;
  for (std::size_t i = 0;; ++i) {
    eoir_property_info info{};
    info.struct_size = sizeof info;
    info.minimum = info.maximum = std::nan("");  // left NaN by a library before 1.3
    const eoir_status st = api().property_info_at(engine_, object.c_str(), i, &info);
    if (st == EOIR_ERR_OUT_OF_RANGE) break;
    check(st, object + ": property " + std::to_string(i));
    PropertyInfo p;
    p.name = info.name ? info.name : "";
    p.unit = info.unit ? info.unit : "";
    p.description = info.description ? info.description : "";
    p.type = info.type;
    p.fidelity = (info.flags & EOIR_PROPERTY_FIDELITY) != 0;
    p.has_range = !std::isnan(info.minimum) && !std::isnan(info.maximum);
    if (p.has_range) {
      p.minimum = info.minimum;
      p.maximum = info.maximum;
      p.minimum_open = (info.range_open & 1u) != 0;
      p.maximum_open = (info.range_open & 2u) != 0;
      std::string c = info.choices ? info.choices : "";
      for (std::size_t a = 0; !c.empty() && a <= c.size();) {
        const std::size_t b = std::min(c.find(',', a), c.size());
        p.choices.push_back(c.substr(a, b - a));
        a = b + 1;
      }
    }
    out.push_back(std::move(p));
  }
  return out;
}
}  // namespace eoir::cli
