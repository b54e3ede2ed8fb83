// The engine as the CLI sees it: libeoir loaded as a plugin through
// eoir_plugin_loader (never linked), its function table, and one engine.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plugin_loader.h"

namespace eoir::cli {

// An engine call failed. what() is "WHERE: engine message (STATUS_NAME)".
class EngineError : public std::runtime_error {
 public:
  EngineError(const std::string& message, eoir_status status) : std::runtime_error(message), status_(status) {}
  eoir_status status() const { return status_; }

 private:
  eoir_status status_;
};

// How to create the engine: the library (NULL: EOIR_LIBRARY, the one beside
// the program, or the build's), the noise seed and the worker threads
// (0 = all cores).
struct EngineConfig {
  const char* library = nullptr;
  uint64_t seed = 1;
  uint32_t threads = 0;
};

// One entry of an object's property table (eoir_property_info), in the
// engine's order. has_range is false where the library predates C ABI 1.3.
struct PropertyInfo {
  std::string name, unit, description;
  int32_t type = 0;
  bool fidelity = false;
  bool has_range = false;
  double minimum = 0, maximum = 0;
  bool minimum_open = false, maximum_open = false;
  std::vector<std::string> choices;
};

class Engine {
 public:
  // Throws std::runtime_error with the loader's or the engine's message.
  explicit Engine(const char* library = nullptr, bool verbose = false);
  explicit Engine(const EngineConfig& config, bool verbose = false);
  ~Engine();
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  const eoir_api_v1& api() const { return *plugin_.api; }
  eoir_engine handle() const { return engine_; }
  const char* library_path() const { return plugin_.path; }
  // Throws EngineError("where: last_error (STATUS)") if status is an error.
  void check(eoir_status status, const std::string& where) const;
  // The property table of an existing object or sensor.
  std::vector<PropertyInfo> properties(const std::string& object) const;
  // The current value of a property as JSON (null for a non-finite number).
  nlohmann::ordered_json value(const std::string& object, const std::string& name, int32_t type) const;

 private:
  eoir_loader_plugin plugin_{};
  eoir_host_api host_{};
  eoir_engine engine_ = nullptr;
  bool verbose_ = false;
};

}  // namespace eoir::cli
