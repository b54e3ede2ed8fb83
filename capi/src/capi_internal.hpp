// Shared pieces of the C ABI implementation: the engine handle (an engine and
// the mutex that serializes calls on it), the guard that turns every C++
// exception into a status and a thread-local message, and argument checks.
// Everything here translates; the engine computes.
#pragma once
#include <cstring>
#include <memory>
#include <mutex>
#include <string>

#include "core/error.hpp"
#include "core/utf8.hpp"
#include "engine.hpp"
#include "eoir/eoir.h"

struct eoir_engine_s {
  std::mutex mutex;  // one call at a time on one engine (eoir.h "Threads")
  std::unique_ptr<eoir::Engine> engine;
};

namespace eoir::capi {

void set_last_error(eoir_status status, const std::string& message);
void clear_last_error();

// Runs f(); returns EOIR_OK or the status of the exception it threw. No
// exception ever leaves this function.
template <class F>
eoir_status guarded(F&& f) noexcept {
  try {
    f();
    clear_last_error();
    return EOIR_OK;
  } catch (const eoir::Error& e) {
    set_last_error(static_cast<eoir_status>(e.status()), e.what());
    return static_cast<eoir_status>(e.status());
  } catch (const std::bad_alloc&) {
    set_last_error(EOIR_ERR_INTERNAL, "out of memory");
    return EOIR_ERR_INTERNAL;
  } catch (const std::exception& e) {
    set_last_error(EOIR_ERR_INTERNAL, std::string("internal error: ") + e.what());
    return EOIR_ERR_INTERNAL;
  } catch (...) {
    set_last_error(EOIR_ERR_INTERNAL, "internal error: unknown exception");
    return EOIR_ERR_INTERNAL;
  }
}

// Throw eoir::Error(null_argument) naming `field` if p is NULL.
inline void need(const void* p, const char* field) {
  if (!p) throw Error(Status::null_argument, std::string(field) + ": must not be NULL");
}
// Runs f(engine) holding the handle's lock: calls on one engine from several
// threads are serialized, never interleaved.
template <class F>
eoir_status with_engine(eoir_engine handle, F&& f) noexcept {
  return guarded([&] {
    need(handle, "engine");
    std::lock_guard<std::mutex> lock(handle->mutex);
    f(*handle->engine);
  });
}
// A struct passed in must declare at least `minimum` bytes.
inline void need_size(uint32_t struct_size, size_t minimum, const char* field) {
  if (struct_size < minimum)
    throw Error(Status::struct_size, std::string(field) + ".struct_size: " + std::to_string(struct_size) +
                                         " is smaller than the " + std::to_string(minimum) + " bytes of ABI v1");
}
// Copies `text` into a char array of the ABI (object names, catalogue ids):
// at most N - 1 bytes, cut at a UTF-8 character boundary, NUL-terminated.
template <std::size_t N>
void copy_text(char (&out)[N], const std::string& text) {
  const std::size_t n = utf8_prefix_length(text, N - 1);
  std::memcpy(out, text.data(), n);
  out[n] = '\0';
}
inline std::string str(const char* s, const char* field) {
  need(s, field);
  return s;
}
// A time scale of eoir.h; throws out_of_range naming `field` if unknown.
TimeScale scale_of(int32_t scale, const std::string& field);
// The engine time of *t; throws naming `field` ("time.jd1", "times[2].scale")
// if t is NULL, of an unknown scale or outside the accepted dates (eoir.h).
EngineTime time_of(const eoir_time* t, const std::string& field);
// The host's callbacks (eoir_plugin_entry) as engine options.
void attach_host_services(EngineOptions& options);

}  // namespace eoir::capi
