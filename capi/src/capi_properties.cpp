// Typed property access for objects and sensors.
#include <cstddef>
#include <cstring>
#include <mutex>
#include <string>
#include <unordered_map>

#include "capi_internal.hpp"
#include "universe/object_properties.hpp"

using namespace eoir;
using eoir::capi::guarded;
using eoir::capi::need;
using eoir::capi::str;
using eoir::capi::with_engine;

namespace {
// The closed set of a string property as "a,b,c", kept for the life of the
// library (the property tables are static).
const char* choices_text(const PropertySpec<universe::Object>& spec) {
  static std::mutex mutex;
  static std::unordered_map<const void*, std::string> texts;
  std::lock_guard<std::mutex> lock(mutex);
  auto [it, inserted] = texts.try_emplace(&spec);
  if (inserted)
    for (const auto& c : spec.choices) it->second += (it->second.empty() ? "" : ",") + c;
  return it->second.c_str();
}

eoir_status set(eoir_engine engine, const char* object, const char* property, const Value& value) {
  return with_engine(engine, [&](Engine& e) { e.set_property(str(object, "object"), str(property, "property"), value); });
}

Value get(const Engine& e, const char* object, const char* property, ValueType expected) {
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
  return set(engine, object, property, Value(value));
}
EOIR_API eoir_status eoir_set_integer(eoir_engine engine, const char* object, const char* property, int64_t value) {
  return set(engine, object, property, Value(static_cast<std::int64_t>(value)));
}
EOIR_API eoir_status eoir_set_bool(eoir_engine engine, const char* object, const char* property, int32_t value) {
  if (value != 0 && value != 1)
    return guarded([&] {
      throw Error(Status::out_of_range,
                  (property ? property : "value") + std::string(": a bool is 0 or 1, got ") + std::to_string(value));
    });
  return set(engine, object, property, Value(value != 0));
}
EOIR_API eoir_status eoir_set_string(eoir_engine engine, const char* object, const char* property,
                                     const char* value) {
  if (!value) return guarded([&] { need(value, "value"); });
  return set(engine, object, property, Value(std::string(value)));
}
EOIR_API eoir_status eoir_set_array(eoir_engine engine, const char* object, const char* property,
                                    const double* values, size_t count) {
  constexpr size_t max_array = 1u << 20;
  if ((count > 0 && !values) || count > max_array)
    return guarded([&] {
      need(values, "values");
      throw Error(Status::limit_exceeded, (property ? property : "values") + std::string(": at most ") +
                                              std::to_string(max_array) + " values, got a count of " +
                                              std::to_string(count));
    });
  return set(engine, object, property, Value(std::vector<double>(values, values + count)));
}

EOIR_API eoir_status eoir_get_number(eoir_engine engine, const char* object, const char* property,
                                     double* value_out) {
  return with_engine(engine, [&](Engine& e) {
    need(value_out, "value_out");
    *value_out = std::get<double>(get(e, object, property, ValueType::number));
  });
}
EOIR_API eoir_status eoir_get_integer(eoir_engine engine, const char* object, const char* property,
                                      int64_t* value_out) {
  return with_engine(engine, [&](Engine& e) {
    need(value_out, "value_out");
    *value_out = std::get<std::int64_t>(get(e, object, property, ValueType::integer));
  });
}
EOIR_API eoir_status eoir_get_bool(eoir_engine engine, const char* object, const char* property,
                                   int32_t* value_out) {
  return with_engine(engine, [&](Engine& e) {
    need(value_out, "value_out");
    *value_out = std::get<bool>(get(e, object, property, ValueType::boolean)) ? 1 : 0;
  });
}
EOIR_API eoir_status eoir_get_string(eoir_engine engine, const char* object, const char* property, char* buffer,
                                     size_t capacity) {
  return with_engine(engine, [&](Engine& e) {
    need(buffer, "buffer");
    const std::string s = std::get<std::string>(get(e, object, property, ValueType::string));
    if (s.size() + 1 > capacity)
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(s.size() + 1) + " bytes needed");
    std::memcpy(buffer, s.c_str(), s.size() + 1);
  });
}
EOIR_API eoir_status eoir_get_array(eoir_engine engine, const char* object, const char* property, double* values,
                                    size_t capacity, size_t* count_out) {
  return with_engine(engine, [&](Engine& e) {
    need(count_out, "count_out");
    const auto a = std::get<std::vector<double>>(get(e, object, property, ValueType::array));
    *count_out = a.size();
    if (!values) return;
    if (a.size() > capacity)
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(a.size()) + " values needed");
    std::copy(a.begin(), a.end(), values);
  });
}

EOIR_API eoir_status eoir_property_info_at(eoir_engine engine, const char* object, size_t index,
                                           eoir_property_info* info_out) {
  return with_engine(engine, [&](Engine& e) {
    const universe::Object& o = e.universe().get(str(object, "object"));
    need(info_out, "info_out");
    constexpr size_t v1_size = offsetof(eoir_property_info, flags);  // the struct before 1.3 appended flags
    capi::need_size(info_out->struct_size, v1_size, "info_out");
    const auto& specs = universe::properties_of(o.kind);
    if (index >= specs.size())
      throw Error(Status::out_of_range, "index: " + std::to_string(index) + " >= property count " +
                                            std::to_string(specs.size()));
    const auto& s = specs[index];
    info_out->name = s.name;
    info_out->type = static_cast<int32_t>(s.type);
    info_out->unit = s.unit;
    info_out->description = s.description;
    const auto covers = [&](size_t offset, size_t size) { return info_out->struct_size >= offset + size; };
    if (covers(offsetof(eoir_property_info, flags), sizeof info_out->flags))
      info_out->flags = s.fidelity ? EOIR_PROPERTY_FIDELITY : 0;
    if (covers(offsetof(eoir_property_info, range_open), sizeof info_out->range_open))
      info_out->range_open = (s.range.min_open ? 1u : 0u) | (s.range.max_open ? 2u : 0u);
    if (covers(offsetof(eoir_property_info, minimum), sizeof info_out->minimum)) info_out->minimum = s.range.min;
    if (covers(offsetof(eoir_property_info, maximum), sizeof info_out->maximum)) info_out->maximum = s.range.max;
    if (covers(offsetof(eoir_property_info, choices), sizeof info_out->choices)) info_out->choices = choices_text(s);
  });
}
}
