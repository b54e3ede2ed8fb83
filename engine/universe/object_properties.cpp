#include "universe/object_properties.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "universe/composite.hpp"
#include "universe/sensor_properties.hpp"

namespace eoir::universe {
namespace {
using Spec = PropertySpec<Object>;

// Physical bounds: every value a property takes stays finite through the
// whole model (Planck to 1e6 K, geometry in double relative to the observer).
constexpr double max_temperature_K = 1.0e6;
constexpr double max_length_m = 1.0e12;

void refuse_central_body(const Object& o, const char* field) {
  if (o.kind == ObjectKind::central_body)
    throw Error(Status::not_allowed,
                std::string(field) + ": the dimensions of central body '" + o.name + "' are fixed (spec 4.1.5.1)");
}

std::vector<std::string> shape_names() {
  std::vector<std::string> names;
  for (const auto& s : shapes()) names.push_back(s.name);
  return names;
}

std::vector<Spec> body_properties(bool missile) {
  std::vector<Spec> t;
  Spec shape = enum_property<Object, ShapeKind>(
      "shape",
      "Shape (spec 4.1.5.1): sphere, oblate, box, plate, cylinder, cone, coupler, none or composite; a change to a "
      "shape taking another number of dimensions resets dimensions_m to 1 m each",
      [](Object& o) -> auto& { return o.body.shape; }, shape_names());
  const auto set_shape = shape.set;
  shape.set = [set_shape](Object& o, const Value& v) {
    refuse_central_body(o, "shape");
    set_shape(o, v);
    const std::size_t n = shape_info(o.body.shape).dimensions.size();
    if (o.body.dimensions_m.size() != n) o.body.dimensions_m.assign(n, 1.0);
  };
  t.push_back(shape);
  t.push_back(Spec{"dimensions_m", ValueType::array, "m",
                   "Dimensions of the shape: sphere [radius], oblate [equatorial, polar radius], box [x, y, z], plate "
                   "[x, y], cylinder [radius, length], cone [base radius, length], coupler [base radius, top radius, "
                   "length], none []",
                   [](const Object& o) { return Value(o.body.dimensions_m); },
                   [](Object& o, const Value& v) {
                     refuse_central_body(o, "dimensions_m");
                     const auto& a = array_of(v, "dimensions_m");
                     check_dimensions(o.body.shape, a, "dimensions_m");
                     for (std::size_t i = 0; i < a.size(); ++i)
                       check_range(a[i], Range{0, max_length_m, true}, "dimensions_m[" + std::to_string(i) + "]", "m");
                     o.body.dimensions_m = a;
                   },
                   Range{0, max_length_m, true}});
  t.push_back(Spec{"material", ValueType::string, "",
                   "Surface material (spec 4.1.4.1, 4.3.3-4.3.5, Appendix A): gray_body (flat SRF = reflectance, "
                   "Lambertian) or a material of the data folder or the user's (eoir_material_add)",
                   [](const Object& o) { return Value(o.body.material); },
                   [](Object& o, const Value& v) {
                     const std::string& m = string_of(v, "material");
                     if (m.empty()) throw Error(Status::unknown_name, "material: must not be empty");
                     o.body.material = m;  // the engine checks the name against its materials
                   }});
  t.push_back(number_property<Object>("temperature_K", "K", "Surface temperature (uniform thermal model)",
                                      [](Object& o) -> auto& { return o.body.temperature_K; },
                                      Range{0, max_temperature_K}));
  t.push_back(number_property<Object>("reflectance", "",
                                      "Gray-body spectral reflectance SRF in [0, 1]; emissivity = 1 - SRF (spec 4.1.4.1)",
                                      [](Object& o) -> auto& { return o.body.reflectance; }, Range{0, 1}));
  t.push_back(Spec{"composite", ValueType::string, "",
                   "Parts of shape composite as a JSON array: {shape, dimensions_m, offset_m, orientation_wxyz, "
                   "temperature_K, reflectance, material} or nested {parts, offset_m, orientation_wxyz} (spec 4.1.5.1), or the "
                   "name of a predefined satellite (spec 4.3.3: leo_earth_observing, leo_communications, "
                   "geo_communications), which stands for its parts",
                   [](const Object& o) { return Value(o.body.composite); },
                   [](Object& o, const Value& v) {
                     refuse_central_body(o, "composite");
                     const std::string& text = string_of(v, "composite");
                     o.body.composite_parts =
                         std::make_shared<const std::vector<ShapePart>>(parse_composite(text, "composite"));
                     o.body.composite = text;
                   }});
  t.push_back(enum_property<Object, ThermalModel>(
      "thermal_model",
      "uniform (temperature_K everywhere), subsolar (spec 4.3.1.3 eq. 12: T_ss cos^(1/4) of the angle from the "
      "subsolar point by day, cooling toward night_temperature_K by night), eclipse (temperature_K in "
      "sunlight, eclipse_temperature_K in shadow) or climatology (the Earth: diurnal cycle of the monthly "
      "minimum and maximum of its latitude, land or water; spec 4.3.1.3)",
      [](Object& o) -> auto& { return o.body.thermal_model; }, thermal_model_names()));
  t.push_back(number_property<Object>("subsolar_temperature_K", "K", "T_ss of the subsolar thermal model (eq. 12)",
                                      [](Object& o) -> auto& { return o.body.subsolar_temperature_K; },
                                      Range{0, max_temperature_K}));
  t.push_back(number_property<Object>("night_temperature_K", "K",
                                      "Night-side temperature of the subsolar thermal model",
                                      [](Object& o) -> auto& { return o.body.night_temperature_K; },
                                      Range{0, max_temperature_K}));
  t.push_back(number_property<Object>("eclipse_temperature_K", "K",
                                      "Thermal model eclipse: the temperature in full shadow (radiative equilibrium "
                                      "T^4 = T_e^4 + f (T^4 - T_e^4) with the visible fraction f of the solar disc)",
                                      [](Object& o) -> auto& { return o.body.eclipse_temperature_K; },
                                      Range{0, max_temperature_K}));
  t.push_back(enum_property<Object, PointSourceModel>(
      "point_source_model",
      "Imaged smaller than a sample (spec 4.1.6.1): detailed (sum over the visible tessellations), simple "
      "(Lambertian sphere with the phase law) or automatic (detailed for satellites and missiles)",
      [](Object& o) -> auto& { return o.body.point_source_model; }, point_source_model_names()));
  t.push_back(Spec{"spectrum", ValueType::string, "",
                   "Tabulated self-radiance (spec 4.1.4): the name of an entry of the engine's spectrum table "
                   "(\"sun\", or one added with eoir_spectrum_add) used instead of eps B(T); \"\" for none",
                   [](const Object& o) { return Value(o.body.spectrum); },
                   [](Object& o, const Value& v) { o.body.spectrum = string_of(v, "spectrum"); }});
  t.push_back(number_property<Object>(
      "patch_size_m", "m",
      "Edge of the patches dA the surface is divided into (spec 4.1.5.2); 0 = automatic (the imaging sensor's "
      "fidelity: 785 km at the Earth's radius for central bodies, an eighth of the object's size otherwise)",
      [](Object& o) -> auto& { return o.body.patch_size_m; }, Range{0, max_length_m}));
  if (missile) {
    Spec stages = integer_property<Object>("stages", "count", "Number of stages, 1-18 (spec 4.3.6)",
                                           [](Object& o) -> auto& { return o.body.stages; },
                                           Range{1, static_cast<double>(limits::max_missile_stages)});
    const auto set_stages = stages.set;
    stages.set = [set_stages](Object& o, const Value& v) {
      if (integer_of(v, "stages") > static_cast<std::int64_t>(limits::max_missile_stages))
        throw Error(Status::limit_exceeded, "stages: at most " + std::to_string(limits::max_missile_stages) +
                                                " stages per missile, got " + std::to_string(integer_of(v, "stages")));
      set_stages(o, v);
    };
    t.push_back(stages);
  }
  return t;
}

std::vector<Spec> star_field_properties() {
  std::vector<Spec> t;
  t.push_back(number_property<Object>(
      "limiting_magnitude", "mag",
      "Faintest Johnson V magnitude of the catalogue stars imaged (spec 4.3.2); past the catalogue's faintest star "
      "every star is used and the engine logs a warning",
      [](Object& o) -> auto& { return o.stars.limiting_magnitude; }, Range{-30, 30}));
  t.push_back(Spec{"catalog_file", ValueType::string, "",
                   "Star catalogue: \"\" for the data folder's Hipparcos/Tycho catalogue (kstars-data, V <= 9), or "
                   "the path of a CSV file with columns id, ra_deg, dec_deg, pm_ra_mas_yr, pm_dec_mas_yr, "
                   "parallax_mas, v_mag, b_v (README \"Stars\"); read and checked when set",
                   [](const Object& o) { return Value(o.stars.catalog_file); },
                   [](Object& o, const Value& v) { o.stars.catalog_file = string_of(v, "catalog_file"); }});
  t.push_back(number_property<Object>("catalog_epoch_year", "yr",
                                      "Epoch of the CSV catalogue's positions and origin of its proper motions "
                                      "(TDB Julian year, e.g. 2016.0 for Gaia DR3)",
                                      [](Object& o) -> auto& { return o.stars.catalog_epoch_year; },
                                      Range{1000, 3000}));
  t.push_back(bool_property<Object>(
      "background_light",
      "Background light of spec 4.1.4 (integrated starlight, zodiacal light, airglow): E_bkg SRF / pi on every "
      "surface (eq. 4) and E_bkg / pi as the radiance of samples that see no object",
      [](Object& o) -> auto& { return o.stars.background_light; }));
  t.push_back(number_property<Object>(
      "zodiacal_light_scale", "-",
      "Scale of the zodiacal light: 1 = Leinert et al. (1998) Table 19, 90 deg elongation in the ecliptic (202 S10); "
      "0.297 = the ecliptic pole (60 S10)",
      [](Object& o) -> auto& { return o.stars.zodiacal_light_scale; }, Range{0, 100}));
  return t;
}

std::vector<Spec> sensor_object_properties() {
  std::vector<Spec> t;
  for (const auto& s : sensor_properties()) {
    const auto get = s.get;
    const auto set = s.set;
    t.push_back(Spec{s.name, s.type, s.unit, s.description, [get](const Object& o) { return get(o.sensor); },
                     [set](Object& o, const Value& v) { set(o.sensor, v); }, s.range, s.choices, s.fidelity});
  }
  return t;
}
}  // namespace

const std::vector<std::string>& thermal_model_names() {
  static const std::vector<std::string> names{"uniform", "subsolar", "eclipse", "climatology"};
  return names;
}

const std::vector<std::string>& point_source_model_names() {
  static const std::vector<std::string> names{"automatic", "detailed", "simple"};
  return names;
}

std::vector<ShapePart> shape_parts(const BodyProperties& body) {
  if (body.shape == ShapeKind::composite) return *body.composite_parts;
  if (body.shape == ShapeKind::none) return {};
  ShapePart part;
  part.kind = body.shape;
  part.dimensions_m = body.dimensions_m;
  return {part};
}

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
