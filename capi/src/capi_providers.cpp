// The report-generator interface: groups, elements, values.
#include "capi_internal.hpp"

using namespace eoir;
using eoir::capi::guarded;
using eoir::capi::need;
using eoir::capi::str;

namespace {
// Times of one eoir_provider_series call (eoir.h): 46 days at 1 s.
constexpr size_t max_series_times = size_t{1} << 22;

const std::vector<metrics::GroupSpec>& groups() { return metrics::provider_groups(); }
const metrics::GroupSpec& group_named(const std::string& name) { return metrics::provider_group(name); }

int32_t type_of(metrics::ElementType t) {
  switch (t) {
    case metrics::ElementType::number: return EOIR_TYPE_NUMBER;
    case metrics::ElementType::integer: return EOIR_TYPE_INTEGER;
    case metrics::ElementType::boolean: return EOIR_TYPE_BOOL;
    case metrics::ElementType::curve: return EOIR_TYPE_CURVE;
  }
  return 0;
}

metrics::ElementValue evaluate(Engine& e, const char* group, const char* element, const char* sensor,
                               const char* target) {
  return e.provider(str(group, "group"), str(element, "element"), str(sensor, "sensor"), target ? target : "");
}
}  // namespace

extern "C" {

EOIR_API eoir_status eoir_provider_group_at(size_t index, const char** group_out) {
  return guarded([&] {
    need(group_out, "group_out");
    if (index >= groups().size())
      throw Error(Status::out_of_range, "index: " + std::to_string(index) + " >= group count " +
                                            std::to_string(groups().size()));
    *group_out = groups()[index].name;
  });
}

EOIR_API eoir_status eoir_provider_element_at(const char* group, size_t index, eoir_element_info* info_out) {
  return guarded([&] {
    const metrics::GroupSpec& g = group_named(str(group, "group"));
    need(info_out, "info_out");
    capi::need_size(info_out->struct_size, sizeof(eoir_element_info), "info_out");
    if (index >= g.elements.size())
      throw Error(Status::out_of_range, "index: " + std::to_string(index) + " >= element count " +
                                            std::to_string(g.elements.size()) + " of '" + g.name + "'");
    const auto& el = g.elements[index];
    info_out->name = el.name;
    info_out->type = type_of(el.type);
    info_out->unit = el.unit;
    info_out->x_unit = el.x_unit ? el.x_unit : "";
  });
}

EOIR_API eoir_status eoir_provider_get(eoir_engine engine, const char* group, const char* element,
                                       const char* sensor, const char* target, double* value_out) {
  return capi::with_engine(engine, [&](Engine& e) {
    need(value_out, "value_out");
    const metrics::ElementValue v = evaluate(e, group, element, sensor, target);
    if (v.type == metrics::ElementType::curve)
      throw Error(Status::type_mismatch,
                  std::string("element: '") + element + "' is a curve; read it with eoir_provider_get_curve");
    *value_out = v.number;
  });
}

EOIR_API eoir_status eoir_provider_get_curve(eoir_engine engine, const char* group, const char* element,
                                             const char* sensor, const char* target, double* x, double* y,
                                             size_t capacity, size_t* count_out) {
  return capi::with_engine(engine, [&](Engine& e) {
    need(count_out, "count_out");
    const metrics::ElementValue v = evaluate(e, group, element, sensor, target);
    if (v.type != metrics::ElementType::curve || !v.curve)
      throw Error(Status::type_mismatch,
                  std::string("element: '") + element + "' is a scalar; read it with eoir_provider_get");
    const auto& fx = v.curve->frequency_cycles_per_mrad;
    const auto& fy = v.curve->value;
    *count_out = fy.size();
    if (!x || !y) return;
    if (fy.size() > capacity)
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(fy.size()) + " points needed");
    std::copy(fx.begin(), fx.end(), x);
    std::copy(fy.begin(), fy.end(), y);
  });
}

EOIR_API eoir_status eoir_provider_series(eoir_engine engine, const char* group, const char* element,
                                          const char* sensor, const char* target, const eoir_time* times,
                                          size_t count, double* values_out) {
  return capi::with_engine(engine, [&](Engine& e) {
    if (count > 0) {
      need(times, "times");
      need(values_out, "values_out");
    }
    if (count > max_series_times)
      throw Error(Status::limit_exceeded, "count: at most " + std::to_string(max_series_times) + " times, got " +
                                              std::to_string(count));
    std::vector<EngineTime> t;
    t.reserve(count);
    for (size_t i = 0; i < count; ++i) t.push_back(capi::time_of(&times[i], "times[" + std::to_string(i) + "]"));
    const std::vector<double> v =
        e.provider_series(str(group, "group"), str(element, "element"), str(sensor, "sensor"), target ? target : "", t);
    std::copy(v.begin(), v.end(), values_out);
  });
}
}
