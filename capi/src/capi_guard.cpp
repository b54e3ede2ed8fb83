// Thread-local last error, status names and the version queries.
#include <string>

#include "capi_internal.hpp"

namespace eoir::capi {
namespace {
thread_local std::string last_message;
}
void set_last_error(eoir_status, const std::string& message) { last_message = message; }
void clear_last_error() { last_message.clear(); }
}  // namespace eoir::capi

extern "C" {

EOIR_API const char* eoir_last_error(void) { return eoir::capi::last_message.c_str(); }

EOIR_API const char* eoir_status_name(eoir_status status) {
  switch (status) {
    case EOIR_OK: return "EOIR_OK";
    case EOIR_ERR_NULL_ARGUMENT: return "EOIR_ERR_NULL_ARGUMENT";
    case EOIR_ERR_STRUCT_SIZE: return "EOIR_ERR_STRUCT_SIZE";
    case EOIR_ERR_OUT_OF_RANGE: return "EOIR_ERR_OUT_OF_RANGE";
    case EOIR_ERR_UNKNOWN_NAME: return "EOIR_ERR_UNKNOWN_NAME";
    case EOIR_ERR_TYPE_MISMATCH: return "EOIR_ERR_TYPE_MISMATCH";
    case EOIR_ERR_BUFFER_TOO_SMALL: return "EOIR_ERR_BUFFER_TOO_SMALL";
    case EOIR_ERR_LIMIT_EXCEEDED: return "EOIR_ERR_LIMIT_EXCEEDED";
    case EOIR_ERR_ALREADY_EXISTS: return "EOIR_ERR_ALREADY_EXISTS";
    case EOIR_ERR_NOT_ALLOWED: return "EOIR_ERR_NOT_ALLOWED";
    case EOIR_ERR_NO_STATE: return "EOIR_ERR_NO_STATE";
    case EOIR_ERR_IO: return "EOIR_ERR_IO";
    case EOIR_ERR_CORRUPT_FILE: return "EOIR_ERR_CORRUPT_FILE";
    case EOIR_ERR_FILE_VERSION: return "EOIR_ERR_FILE_VERSION";
    case EOIR_ERR_ABI_MISMATCH: return "EOIR_ERR_ABI_MISMATCH";
    case EOIR_ERR_CANCELLED: return "EOIR_ERR_CANCELLED";
    case EOIR_ERR_INTERNAL: return "EOIR_ERR_INTERNAL";
    default: return "EOIR_ERR_UNKNOWN_STATUS";
  }
}

EOIR_API uint32_t eoir_version(void) {
  return EOIR_VERSION_MAJOR * 10000u + EOIR_VERSION_MINOR * 100u + EOIR_VERSION_PATCH;
}

EOIR_API const char* eoir_version_string(void) {
#define EOIR_STR2(x) #x
#define EOIR_STR(x) EOIR_STR2(x)
  return EOIR_STR(EOIR_VERSION_MAJOR) "." EOIR_STR(EOIR_VERSION_MINOR) "." EOIR_STR(EOIR_VERSION_PATCH);
}
}
