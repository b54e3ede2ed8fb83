#include "geometry/embree_device.hpp"

#include <mutex>
#include <string>

#include "core/error.hpp"

namespace eoir::geometry {
namespace {

// The device's errors are recorded here.
std::mutex g_error_mutex;
std::string g_error_message;

void on_embree_error(void*, RTCError code, const char* message) {
  std::lock_guard<std::mutex> lock(g_error_mutex);
  g_error_message = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

}  // namespace

RTCDevice embree_device() {
  static std::once_flag once;
  static RTCDevice device = nullptr;
  std::call_once(once, [] {
    device = rtcNewDevice(nullptr);
    if (device) rtcSetDeviceErrorFunction(device, on_embree_error, nullptr);
  });
  if (!device) throw Error(Status::internal, "Embree: rtcNewDevice failed (" + std::to_string(rtcGetDeviceError(nullptr)) + ")");
  return device;
}

void check_embree(RTCDevice device, const char* what) {
  const RTCError code = rtcGetDeviceError(device);
  if (code == RTC_ERROR_NONE) return;
  std::lock_guard<std::mutex> lock(g_error_mutex);
  throw Error(Status::internal, std::string("ray caster: ") + what + ": " + g_error_message);
}

}  // namespace eoir::geometry
