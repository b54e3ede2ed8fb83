// A typed property value and the description of a named property, shared by
// objects, sensors and fidelity knobs (the C ABI's eoir_set_* / eoir_get_*,
// the .scd file and the property listing).
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <variant>
#include <vector>

namespace eoir {

enum class ValueType : int { number = 1, integer = 2, boolean = 3, string = 4, array = 5 };

using Value = std::variant<double, std::int64_t, bool, std::string, std::vector<double>>;

const char* value_type_name(ValueType type);
ValueType value_type_of(const Value& value);

// The values a number, an integer or each element of an array may take.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  // min itself excluded (e.g. "> 0")
  bool max_open = false;
  bool contains(double x) const {
    return (min_open ? x > min : x >= min) && (max_open ? x < max : x <= max);
  }
  // "(0, 180)", "[1, 16384]"
  std::string text() const;
};

// One named property of an object type T. `set` validates and throws
// eoir::Error naming the field; `get` never throws.
template <class T>
struct PropertySpec {
  const char* name;
  ValueType type;
  const char* unit;
  const char* description;
  std::function<Value(const T&)> get;
  std::function<void(T&, const Value&)> set;
  Range range{};                     // numbers, integers and array elements
  std::vector<std::string> choices{};  // strings with a closed set of values
  bool fidelity = false;             // a knob trading speed for accuracy (core/fidelity.hpp)
};

// Conversions used by every property setter; each throws eoir::Error
// (type_mismatch, out_of_range) naming `field`.
double number_of(const Value& v, const std::string& field);
std::int64_t integer_of(const Value& v, const std::string& field);
bool bool_of(const Value& v, const std::string& field);
const std::string& string_of(const Value& v, const std::string& field);
const std::vector<double>& array_of(const Value& v, const std::string& field);
// Throws out_of_range "field: must be in RANGE UNIT, got X" (and for NaN/inf).
void check_range(double x, const Range& range, const std::string& field, const std::string& unit = "");
// Throws unknown_name "field: unknown value 'value' (list)".
[[noreturn]] void throw_unknown_choice(const std::string& field, const std::string& value, const std::string& list);

// Property builders over an accessor `access(T&) -> X&` to the field.
template <class T, class Access>
PropertySpec<T> number_property(const char* name, const char* unit, const char* description, Access access,
                                Range range, bool fidelity = false) {
  return PropertySpec<T>{name, ValueType::number, unit, description,
                         [access](const T& o) { return Value(access(const_cast<T&>(o))); },
                         [=](T& o, const Value& v) {
                           const double x = number_of(v, name);
                           check_range(x, range, name, unit);
                           access(o) = x;
                         },
                         range, {}, fidelity};
}

template <class T, class Access>
PropertySpec<T> integer_property(const char* name, const char* unit, const char* description, Access access,
                                 Range range, bool fidelity = false) {
  return PropertySpec<T>{name, ValueType::integer, unit, description,
                         [access](const T& o) { return Value(access(const_cast<T&>(o))); },
                         [=](T& o, const Value& v) {
                           const std::int64_t x = integer_of(v, name);
                           check_range(static_cast<double>(x), range, name, unit);
                           access(o) = x;
                         },
                         range, {}, fidelity};
}

template <class T, class Access>
PropertySpec<T> bool_property(const char* name, const char* description, Access access, bool fidelity = false) {
  return PropertySpec<T>{name, ValueType::boolean, "", description,
                         [access](const T& o) { return Value(access(const_cast<T&>(o))); },
                         [=](T& o, const Value& v) { access(o) = bool_of(v, name); },
                         Range{}, {}, fidelity};
}

// A string naming one of the values of enumeration E: names[i] is the name
// of static_cast<E>(i).
template <class T, class E, class Access>
PropertySpec<T> enum_property(const char* name, const char* description, Access access,
                              std::vector<std::string> names, bool fidelity = false) {
  return PropertySpec<T>{name, ValueType::string, "", description,
                         [access, names](const T& o) {
                           const auto i = static_cast<std::size_t>(access(const_cast<T&>(o)));
                           return Value(i < names.size() ? names[i] : "invalid(" + std::to_string(i) + ")");
                         },
                         [=](T& o, const Value& v) {
                           const std::string& s = string_of(v, name);
                           for (std::size_t i = 0; i < names.size(); ++i)
                             if (s == names[i]) {
                               access(o) = static_cast<E>(i);
                               return;
                             }
                           std::string list;
                           for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
                           throw_unknown_choice(name, s, list);
                         },
                         Range{}, names, fidelity};
}

// The name of enumerator e among `names` (as enum_property).
template <class E>
const std::string& enum_name(E e, const std::vector<std::string>& names) {
  return names[static_cast<std::size_t>(e)];
}

}  // namespace eoir
