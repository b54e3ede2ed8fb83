#include "engine.hpp"

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
