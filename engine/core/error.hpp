// Errors of the engine: a status code of the C ABI plus a message that names
// the offending field. Thrown inside the engine, caught at the C boundary.
#pragma once
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

namespace eoir {

// Mirrors the EOIR_ERR_* values of capi/include/eoir/eoir.h (never renumbered).
enum class Status : int {
  ok = 0,
  null_argument = -100,
  struct_size = -101,
  out_of_range = -102,
  unknown_name = -103,
  type_mismatch = -104,
  buffer_too_small = -105,
  limit_exceeded = -200,
  already_exists = -201,
  not_allowed = -202,
  no_state = -203,
  io = -300,
  corrupt_file = -301,
  file_version = -302,
  abi_mismatch = -400,
  cancelled = -500,
  internal = -900,
};

class Error : public std::runtime_error {
 public:
  Error(Status status, const std::string& message) : std::runtime_error(message), status_(status) {}
  Status status() const { return status_; }

 private:
  Status status_;
};

// The shortest text that reads back as the same double ("179.9999",
// "100000", "5e-324", "1e+308", "inf"): every number a message quotes.
std::string number_text(double value);

// Throws out_of_range naming `field` (and the value).
[[noreturn]] void throw_not_finite(double value, std::string_view field);
// Throws out_of_range naming `field` unless value is finite (inline: checks
// on every sample cost a compare).
inline void require_finite(double value, std::string_view field) {
  if (!std::isfinite(value)) throw_not_finite(value, field);
}
// Throws out_of_range naming `field` unless value is finite and > 0.
void require_positive(double value, std::string_view field);
// Throws out_of_range naming `field` unless value is finite and >= 0.
void require_non_negative(double value, std::string_view field);

}  // namespace eoir
