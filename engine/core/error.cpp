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

void require_finite(double value, const std::string& field) {
  if (!std::isfinite(value)) throw Error(Status::out_of_range, field + ": not finite (" + describe(value) + ")");
}
void require_positive(double value, const std::string& field) {
  require_finite(value, field);
  if (!(value > 0.0)) throw Error(Status::out_of_range, field + ": must be > 0, got " + describe(value));
}
void require_non_negative(double value, const std::string& field) {
  require_finite(value, field);
  if (value < 0.0) throw Error(Status::out_of_range, field + ": must be >= 0, got " + describe(value));
}
}  // namespace eoir
