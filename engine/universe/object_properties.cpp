#include "universe/object_properties.hpp"

#include <cmath>
#include <tuple>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "sensor/sensor_properties.hpp"
#include "universe/composite.hpp"
#include "universe/materials.hpp"
#include "universe/shapes.hpp"

namespace eoir::universe {
namespace {
using Spec = PropertySpec<Object>;

double number_of(const Value& v, const char* field) {
  if (auto d = std::get_if<double>(&v)) return *d;
  if (auto i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  throw Error(Status::type_mismatch, std::string(field) + ": expects a number");
}
const std::string& string_of(const Value& v, const char* field) {
  if (auto s = std::get_if<std::string>(&v)) return *s;
  throw Error(Status::type_mismatch, std::string(field) + ": expects a string");
}

void refuse_central_body(const Object& o, const char* field) {
  if (o.kind == ObjectKind::central_body)
    throw Error(Status::not_allowed,
                std::string(field) + ": the dimensions of central body '" + o.name + "' are fixed (spec 4.1.5.1)");
}

std::vector<Spec> body_properties(bool missile) {
  std::vector<Spec> t;
  t.push_back(Spec{"shape", ValueType::string, "",
                   "Shape (spec 4.1.5.1): sphere, oblate, box, plate, cylinder, cone, coupler or none; a change of "
                   "shape resets dimensions_m to 1 m each",
                   [](const Object& o) { return Value(o.body.shape); },
                   [](Object& o, const Value& v) {
                     refuse_central_body(o, "shape");
                     const ShapeInfo& s = find_shape(string_of(v, "shape"), "shape");
                     if (o.body.shape != s.name) o.body.dimensions_m.assign(s.dimensions.size(), 1.0);
                     o.body.shape = s.name;
                   }});
  t.push_back(Spec{"dimensions_m", ValueType::array, "m",
                   "Dimensions of the shape: sphere [radius], oblate [equatorial, polar radius], box [x, y, z], plate "
                   "[x, y], cylinder [radius, length], cone [base radius, length], coupler [base radius, top radius, "
                   "length], none []",
                   [](const Object& o) { return Value(o.body.dimensions_m); },
                   [](Object& o, const Value& v) {
                     refuse_central_body(o, "dimensions_m");
                     const auto* a = std::get_if<std::vector<double>>(&v);
                     if (!a) throw Error(Status::type_mismatch, "dimensions_m: expects an array of numbers");
                     check_dimensions(find_shape(o.body.shape, "shape"), *a, "dimensions_m");
                     o.body.dimensions_m = *a;
                   }});
  t.push_back(Spec{"material", ValueType::string, "", "Surface material (spec 4.3.3-4.3.5)",
                   [](const Object& o) { return Value(o.body.material); },
                   [](Object& o, const Value& v) {
                     const std::string& m = string_of(v, "material");
                     check_material(m, "material");
                     o.body.material = m;
                   }});
  t.push_back(Spec{"temperature_K", ValueType::number, "K", "Surface temperature (uniform thermal model)",
                   [](const Object& o) { return Value(o.body.temperature_K); },
                   [](Object& o, const Value& v) {
                     const double x = number_of(v, "temperature_K");
                     require_non_negative(x, "temperature_K");
                     o.body.temperature_K = x;
                   }});
  t.push_back(Spec{"reflectance", ValueType::number, "",
                   "Gray-body spectral reflectance SRF in [0, 1]; emissivity = 1 - SRF (spec 4.1.4.1)",
                   [](const Object& o) { return Value(o.body.reflectance); },
                   [](Object& o, const Value& v) {
                     const double x = number_of(v, "reflectance");
                     require_finite(x, "reflectance");
                     if (x < 0 || x > 1)
                       throw Error(Status::out_of_range, "reflectance: must be in [0, 1], got " + std::to_string(x));
                     o.body.reflectance = x;
                   }});
  t.push_back(Spec{"composite", ValueType::string, "",
                   "Parts of shape composite as a JSON array: {shape, dimensions_m, offset_m, orientation_wxyz, "
                   "temperature_K, reflectance} or nested {parts, offset_m, orientation_wxyz} (spec 4.1.5.1)",
                   [](const Object& o) { return Value(o.body.composite); },
                   [](Object& o, const Value& v) {
                     refuse_central_body(o, "composite");
                     const std::string& text = string_of(v, "composite");
                     parse_composite(text, "composite");  // validates, naming the JSON path
                     o.body.composite = text;
                   }});
  t.push_back(Spec{"thermal_model", ValueType::string, "",
                   "uniform (temperature_K everywhere) or subsolar (spec 4.3.1.3 eq. 12: T_ss cos^(1/4) of the "
                   "angle from the subsolar point by day, night_temperature_K by night)",
                   [](const Object& o) { return Value(o.body.thermal_model); },
                   [](Object& o, const Value& v) {
                     const std::string& m = string_of(v, "thermal_model");
                     if (m != "uniform" && m != "subsolar")
                       throw Error(Status::unknown_name, "thermal_model: unknown model '" + m + "' (uniform, subsolar)");
                     o.body.thermal_model = m;
                   }});
  for (const auto& [name, member, text] :
       {std::tuple<const char*, double BodyProperties::*, const char*>{
            "subsolar_temperature_K", &BodyProperties::subsolar_temperature_K,
            "T_ss of the subsolar thermal model (eq. 12)"},
        {"night_temperature_K", &BodyProperties::night_temperature_K,
         "Night-side temperature of the subsolar thermal model"}}) {
    const char* field = name;
    double BodyProperties::*m = member;
    t.push_back(Spec{field, ValueType::number, "K", text, [m](const Object& o) { return Value(o.body.*m); },
                     [field, m](Object& o, const Value& v) {
                       const double x = number_of(v, field);
                       require_non_negative(x, field);
                       o.body.*m = x;
                     }});
  }
  t.push_back(Spec{"patch_size_m", ValueType::number, "m",
                   "Edge of the patches dA the surface is divided into (spec 4.1.5.2); 0 = automatic (785 km for "
                   "central bodies as spec 4.2.3, an eighth of the object's size otherwise)",
                   [](const Object& o) { return Value(o.body.patch_size_m); },
                   [](Object& o, const Value& v) {
                     const double x = number_of(v, "patch_size_m");
                     require_non_negative(x, "patch_size_m");
                     o.body.patch_size_m = x;
                   }});
  if (missile)
    t.push_back(Spec{"stages", ValueType::integer, "count", "Number of stages, 1-18 (spec 4.3.6)",
                     [](const Object& o) { return Value(o.body.stages); },
                     [](Object& o, const Value& v) {
                       std::int64_t n = 0;
                       if (auto i = std::get_if<std::int64_t>(&v)) n = *i;
                       else if (auto d = std::get_if<double>(&v); d && std::floor(*d) == *d && std::fabs(*d) < 1e9)
                         n = static_cast<std::int64_t>(*d);
                       else throw Error(Status::type_mismatch, "stages: expects an integer");
                       if (n < 1) throw Error(Status::out_of_range, "stages: must be >= 1, got " + std::to_string(n));
                       if (n > static_cast<std::int64_t>(limits::max_missile_stages))
                         throw Error(Status::limit_exceeded, "stages: at most " +
                                                                 std::to_string(limits::max_missile_stages) +
                                                                 " stages per missile, got " + std::to_string(n));
                       o.body.stages = n;
                     }});
  return t;
}

std::vector<Spec> star_field_properties() {
  return {Spec{"limiting_magnitude", ValueType::number, "mag", "Faintest visual magnitude imaged",
               [](const Object& o) { return Value(o.stars.limiting_magnitude); },
               [](Object& o, const Value& v) {
                 const double x = number_of(v, "limiting_magnitude");
                 require_finite(x, "limiting_magnitude");
                 o.stars.limiting_magnitude = x;
               }}};
}

std::vector<Spec> sensor_object_properties() {
  std::vector<Spec> t;
  for (const auto& s : sensor::sensor_properties()) {
    auto get = s.get;
    auto set = s.set;
    t.push_back(Spec{s.name, s.type, s.unit, s.description, [get](const Object& o) { return get(o.sensor); },
                     [set](Object& o, const Value& v) { set(o.sensor, v); }});
  }
  return t;
}
}  // namespace

const std::vector<Spec>& properties_of(ObjectKind kind) {
  static const std::vector<Spec> body = body_properties(false);
  static const std::vector<Spec> missile = body_properties(true);
  static const std::vector<Spec> stars = star_field_properties();
  static const std::vector<Spec> sensors = sensor_object_properties();
  switch (kind) {
    case ObjectKind::star_field: return stars;
    case ObjectKind::missile: return missile;
    case ObjectKind::sensor: return sensors;
    default: return body;
  }
}

const Spec& find_property(const Object& object, const std::string& property) {
  for (const auto& s : properties_of(object.kind))
    if (property == s.name) return s;
  throw Error(Status::unknown_name, "property: " + std::string(kind_name(object.kind)) + " '" + object.name +
                                        "' has no property '" + property + "'");
}

void set_property(Object& object, const std::string& property, const Value& value) {
  const Spec& spec = find_property(object, property);
  // Numbers and integers convert where the spec expects the other; every other
  // mismatch is refused by the setter itself.
  Value v = value;
  if (spec.type == ValueType::number)
    if (auto i = std::get_if<std::int64_t>(&value)) v = static_cast<double>(*i);
  if (auto d = std::get_if<double>(&value)) require_finite(*d, property);
  if (auto a = std::get_if<std::vector<double>>(&value))
    for (size_t k = 0; k < a->size(); ++k) require_finite((*a)[k], property + "[" + std::to_string(k) + "]");
  spec.set(object, v);
  ++object.revision;
}

Value get_property(const Object& object, const std::string& property) {
  return find_property(object, property).get(object);
}

const char* kind_name(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::central_body: return "central_body";
    case ObjectKind::star_field: return "star_field";
    case ObjectKind::satellite: return "satellite";
    case ObjectKind::aircraft: return "aircraft";
    case ObjectKind::ground_vehicle: return "ground_vehicle";
    case ObjectKind::missile: return "missile";
    case ObjectKind::sensor: return "sensor";
  }
  return "?";
}

}  // namespace eoir::universe
