#include "core/error.hpp"

#include <charconv>
#include <cmath>

namespace eoir {

std::string number_text(double value) {
  // Python's repr: the shortest digits that read back, positional from 1e-4
  // to 1e16 ("100000", "179.9999"), scientific beyond ("5e-324").
  const double magnitude = std::fabs(value);
  const bool positional = value == 0.0 || (magnitude >= 1e-4 && magnitude < 1e16);
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value,
                                    positional ? std::chars_format::fixed : std::chars_format::scientific);
  return std::string(text, result.ptr);
}

void throw_not_finite(double value, std::string_view field) {
  throw Error(Status::out_of_range, std::string(field) + ": not finite (" + number_text(value) + ")");
}
void require_positive(double value, std::string_view field) {
  require_finite(value, field);
  if (!(value > 0.0)) throw Error(Status::out_of_range, std::string(field) + ": must be > 0, got " + number_text(value));
}
void require_non_negative(double value, std::string_view field) {
  require_finite(value, field);
  if (value < 0.0) throw Error(Status::out_of_range, std::string(field) + ": must be >= 0, got " + number_text(value));
}
}  // namespace eoir
