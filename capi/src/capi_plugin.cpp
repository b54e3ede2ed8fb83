// The plugin entry point: one exported function returning the append-only
// function table of the requested ABI major (after SQLite's
// sqlite3_api_routines and OpenFX's fetchSuite).
#include <mutex>

#include "capi_internal.hpp"

using eoir::capi::guarded;

namespace {
std::mutex host_mutex;
eoir_host_api host_services{};  // the host's log/progress callbacks (per process)

const eoir_api_v1 api_v1 = {
    sizeof(eoir_api_v1),
    1,
    EOIR_VERSION_MINOR,
    eoir_version,
    eoir_last_error,
    eoir_status_name,
    eoir_engine_create,
    eoir_engine_destroy,
    eoir_engine_set_time,
    eoir_engine_get_time,
    eoir_time_from_iso,
    eoir_time_to_iso,
    eoir_object_add,
    eoir_sensor_add,
    eoir_object_remove,
    eoir_object_count,
    eoir_object_at,
    eoir_object_set_state,
    eoir_object_get_state,
    eoir_set_number,
    eoir_set_integer,
    eoir_set_bool,
    eoir_set_string,
    eoir_set_array,
    eoir_get_number,
    eoir_get_integer,
    eoir_get_bool,
    eoir_get_string,
    eoir_get_array,
    eoir_property_info_at,
    eoir_provider_group_at,
    eoir_provider_element_at,
    eoir_provider_get,
    eoir_provider_get_curve,
    eoir_state_save,
    eoir_state_load,
    eoir_sensor_save,
    eoir_sensor_load,
    eoir_render,
    eoir_image_info_get,
    eoir_image_get,
    eoir_image_get_bytes,
    eoir_pick_get,
    eoir_snr_constraint,
    eoir_truth_count,
    eoir_truth_get,
    eoir_provider_series,
    eoir_material_load,
    eoir_spectrum_add,
    eoir_target_spectrum_get,
    eoir_frame_fidelity_get,
    eoir_sensor_point_azel,
    eoir_sensor_point_at,
    eoir_pick_term_get,
    eoir_image_get_adu,
    eoir_engine_set_limits,
    eoir_engine_get_limits,
};
}  // namespace

namespace eoir::capi {
// Engines created after the host's table arrived report to it: progress
// (cancellation when it returns non-zero) and log messages.
void attach_host_services(EngineOptions& options) {
  eoir_host_api host;
  {
    std::lock_guard<std::mutex> lock(host_mutex);
    host = host_services;
  }
  if (host.progress) {
    options.progress = [host](double fraction, const std::string& what) {
      return host.progress(host.user, fraction, what.c_str()) == 0;
    };
  }
  if (host.log) {
    options.log = [host](int level, const std::string& message) { host.log(host.user, level, message.c_str()); };
  }
}
}  // namespace eoir::capi

extern "C" EOIR_API eoir_status eoir_plugin_entry(uint32_t abi_major, const eoir_host_api* host,
                                                  const void** api_out) {
  return guarded([&] {
    eoir::capi::need(api_out, "api_out");
    *api_out = nullptr;
    if (abi_major != 1)
      throw eoir::Error(eoir::Status::abi_mismatch,
                        "abi_major: the host asks for EOIR ABI major " + std::to_string(abi_major) +
                            "; this engine library (" + eoir_version_string() + ") provides major 1 only");
    if (host) eoir::capi::need_size(host->struct_size, sizeof(eoir_host_api), "host");
    std::lock_guard<std::mutex> lock(host_mutex);
    host_services = host ? *host : eoir_host_api{};  // NULL clears earlier callbacks
    *api_out = &api_v1;
  });
}
