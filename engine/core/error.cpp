#include "core/error.hpp"

#include <cmath>
#include <sstream>

namespace eoir {
namespace {
std::string describe(double value) {
  std::ostringstream s;
  s << value;
  return s.str();
}
}  // namespace

void throw_not_finite(double value, std::string_view field) {
  throw Error(Status::out_of_range, std::string(field) + ": not finite (" + describe(value) + ")");
}
void require_positive(double value, std::string_view field) {
  require_finite(value, field);
  if (!(value > 0.0)) throw Error(Status::out_of_range, std::string(field) + ": must be > 0, got " + describe(value));
}
void require_non_negative(double value, std::string_view field) {
  require_finite(value, field);
  if (value < 0.0) throw Error(Status::out_of_range, std::string(field) + ": must be >= 0, got " + describe(value));
}
}  // namespace eoir
