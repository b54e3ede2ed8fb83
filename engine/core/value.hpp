// A typed property value and the description of a named property, shared by
// objects and sensors (the C ABI's eoir_set_* / eoir_get_* and the .scd file).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace eoir {

enum class ValueType : int { number = 1, integer = 2, boolean = 3, string = 4, array = 5 };

using Value = std::variant<double, std::int64_t, bool, std::string, std::vector<double>>;

const char* value_type_name(ValueType type);
ValueType value_type_of(const Value& value);

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
};

}  // namespace eoir
