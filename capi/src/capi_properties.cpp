// Typed property access for objects and sensors.
#include <cstring>

#include "capi_internal.hpp"
#include "universe/object_properties.hpp"

using namespace eoir;
using eoir::capi::guarded;
using eoir::capi::need;
using eoir::capi::str;

namespace {
void set(eoir_engine engine, const char* object, const char* property, const Value& value) {
  Engine& e = capi::engine_of(engine);
  universe::Object& o = e.universe().get(str(object, "object"));
  universe::set_property(o, str(property, "property"), value);
  e.note_change();
}

Value get(eoir_engine engine, const char* object, const char* property, ValueType expected) {
  Engine& e = capi::engine_of(engine);
  const universe::Object& o = e.universe().get(str(object, "object"));
  const std::string p = str(property, "property");
  const auto& spec = universe::find_property(o, p);
  const bool numeric_ok = expected == ValueType::number && spec.type == ValueType::integer;
  if (spec.type != expected && !numeric_ok)
    throw Error(Status::type_mismatch, "property: '" + p + "' is of type " + value_type_name(spec.type) +
                                           ", not " + value_type_name(expected));
  Value v = spec.get(o);
  if (numeric_ok) v = static_cast<double>(std::get<std::int64_t>(v));
  return v;
}
}  // namespace

extern "C" {

EOIR_API eoir_status eoir_set_number(eoir_engine engine, const char* object, const char* property, double value) {
  return guarded([&] { set(engine, object, property, Value(value)); });
}
EOIR_API eoir_status eoir_set_integer(eoir_engine engine, const char* object, const char* property, int64_t value) {
  return guarded([&] { set(engine, object, property, Value(static_cast<std::int64_t>(value))); });
}
EOIR_API eoir_status eoir_set_bool(eoir_engine engine, const char* object, const char* property, int32_t value) {
  return guarded([&] { set(engine, object, property, Value(value != 0)); });
}
EOIR_API eoir_status eoir_set_string(eoir_engine engine, const char* object, const char* property,
                                     const char* value) {
  return guarded([&] { set(engine, object, property, Value(str(value, "value"))); });
}
EOIR_API eoir_status eoir_set_array(eoir_engine engine, const char* object, const char* property,
                                    const double* values, size_t count) {
  return guarded([&] {
    if (count > 0) need(values, "values");
    set(engine, object, property, Value(std::vector<double>(values, values + count)));
  });
}

EOIR_API eoir_status eoir_get_number(eoir_engine engine, const char* object, const char* property,
                                     double* value_out) {
  return guarded([&] {
    need(value_out, "value_out");
    *value_out = std::get<double>(get(engine, object, property, ValueType::number));
  });
}
EOIR_API eoir_status eoir_get_integer(eoir_engine engine, const char* object, const char* property,
                                      int64_t* value_out) {
  return guarded([&] {
    need(value_out, "value_out");
    *value_out = std::get<std::int64_t>(get(engine, object, property, ValueType::integer));
  });
}
EOIR_API eoir_status eoir_get_bool(eoir_engine engine, const char* object, const char* property,
                                   int32_t* value_out) {
  return guarded([&] {
    need(value_out, "value_out");
    *value_out = std::get<bool>(get(engine, object, property, ValueType::boolean)) ? 1 : 0;
  });
}
EOIR_API eoir_status eoir_get_string(eoir_engine engine, const char* object, const char* property, char* buffer,
                                     size_t capacity) {
  return guarded([&] {
    need(buffer, "buffer");
    const std::string s = std::get<std::string>(get(engine, object, property, ValueType::string));
    if (s.size() + 1 > capacity)
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(s.size() + 1) + " bytes needed");
    std::memcpy(buffer, s.c_str(), s.size() + 1);
  });
}
EOIR_API eoir_status eoir_get_array(eoir_engine engine, const char* object, const char* property, double* values,
                                    size_t capacity, size_t* count_out) {
  return guarded([&] {
    need(count_out, "count_out");
    const auto a = std::get<std::vector<double>>(get(engine, object, property, ValueType::array));
    *count_out = a.size();
    if (!values) return;
    if (a.size() > capacity)
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(a.size()) + " values needed");
    std::copy(a.begin(), a.end(), values);
  });
}

EOIR_API eoir_status eoir_property_info_at(eoir_engine engine, const char* object, size_t index,
                                           eoir_property_info* info_out) {
  return guarded([&] {
    Engine& e = capi::engine_of(engine);
    const universe::Object& o = e.universe().get(str(object, "object"));
    need(info_out, "info_out");
    capi::need_size(info_out->struct_size, sizeof(eoir_property_info), "info_out");
    const auto& specs = universe::properties_of(o.kind);
    if (index >= specs.size())
      throw Error(Status::out_of_range, "index: " + std::to_string(index) + " >= property count " +
                                            std::to_string(specs.size()));
    const auto& s = specs[index];
    info_out->name = s.name;
    info_out->type = static_cast<int32_t>(s.type);
    info_out->unit = s.unit;
    info_out->description = s.description;
  });
}
}
