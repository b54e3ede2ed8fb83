#include "core/value.hpp"

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
ValueType value_type_of(const Value& value) {
  return static_cast<ValueType>(value.index() + 1);
}
}  // namespace eoir
