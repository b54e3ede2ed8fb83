#include "core/value.hpp"

#include <cmath>

#include "core/error.hpp"

namespace eoir {

const char* value_type_name(ValueType type) {
  switch (type) {
    case ValueType::number: return "number";
    case ValueType::integer: return "integer";
    case ValueType::boolean: return "bool";
    case ValueType::string: return "string";
    case ValueType::array: return "array";
  }
  return "?";
}

ValueType value_type_of(const Value& value) { return static_cast<ValueType>(value.index() + 1); }

std::string Range::text() const {
  return std::string(min_open ? "(" : "[") + number_text(min) + ", " + number_text(max) + (max_open ? ")" : "]");
}

double number_of(const Value& v, const std::string& field) {
  if (auto d = std::get_if<double>(&v)) return *d;
  if (auto i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  throw Error(Status::type_mismatch, field + ": expects a number");
}

std::int64_t integer_of(const Value& v, const std::string& field) {
  if (auto i = std::get_if<std::int64_t>(&v)) return *i;
  if (auto d = std::get_if<double>(&v)) {
    if (std::isfinite(*d) && std::floor(*d) == *d && std::fabs(*d) < 9e15) return static_cast<std::int64_t>(*d);
    throw Error(Status::out_of_range, field + ": expects a whole number, got " + number_text(*d));
  }
  throw Error(Status::type_mismatch, field + ": expects an integer");
}

bool bool_of(const Value& v, const std::string& field) {
  if (auto b = std::get_if<bool>(&v)) return *b;
  throw Error(Status::type_mismatch, field + ": expects a bool");
}

const std::string& string_of(const Value& v, const std::string& field) {
  if (auto s = std::get_if<std::string>(&v)) return *s;
  throw Error(Status::type_mismatch, field + ": expects a string");
}

const std::vector<double>& array_of(const Value& v, const std::string& field) {
  if (auto a = std::get_if<std::vector<double>>(&v)) return *a;
  throw Error(Status::type_mismatch, field + ": expects an array of numbers");
}

void check_range(double x, const Range& range, const std::string& field, const std::string& unit) {
  require_finite(x, field);
  if (range.min == 0 && range.min_open && !(x > 0))
    throw Error(Status::out_of_range, field + ": must be > 0, got " + number_text(x));
  if (!range.contains(x))
    throw Error(Status::out_of_range,
                field + ": must be in " + range.text() + (unit.empty() ? "" : " " + unit) + ", got " + number_text(x));
}

void throw_unknown_choice(const std::string& field, const std::string& value, const std::string& list) {
  throw Error(Status::unknown_name, field + ": unknown value '" + value + "' (" + list + ")");
}

}  // namespace eoir
