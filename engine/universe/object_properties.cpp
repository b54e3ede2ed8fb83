#include "universe/object_properties.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "universe/composite.hpp"
#include "universe/object_bounds.hpp"
#include "universe/sensor_properties.hpp"

namespace eoir::universe {
namespace {
using Spec = PropertySpec<Object>;

// Physical bounds (object_bounds.hpp): every value a property takes stays
// finite through the whole model.
constexpr double max_temperature_K = object_bounds::max_temperature_K;
constexpr double max_length_m = object_bounds::max_length_m;

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
      "Shape (spec 4.1.5.1): sphere, oblate, box, plate, cylinder, cone, coupler, none, composite, mesh (a 3-D "
      "model file, mesh_file) or plume (spec 4.3.6); a change to a shape taking another number of dimensions resets "
      "dimensions_m to 1 m each (plume: 1 m, 3 m)",
      [](Object& o) -> auto& { return o.body.shape; }, shape_names());
  const auto set_shape = shape.set;
  shape.set = [set_shape](Object& o, const Value& v) {
    refuse_central_body(o, "shape");
    set_shape(o, v);
    const std::size_t n = shape_info(o.body.shape).dimensions.size();
    if (o.body.dimensions_m.size() != n) o.body.dimensions_m.assign(n, 1.0);
    if (o.body.shape == ShapeKind::plume && !(o.body.dimensions_m[1] > 2.0 * o.body.dimensions_m[0]))
      o.body.dimensions_m = {1.0, 3.0};  // (1 m and 1 m has no cone)
  };
  t.push_back(shape);
  t.push_back(Spec{"dimensions_m", ValueType::array, "m",
                   "Dimensions of the shape: sphere [radius], oblate [equatorial, polar radius], box [x, y, z], plate "
                   "[x, y], cylinder [radius, length], cone [base radius, length], coupler [base radius, top radius, "
                   "length], plume [sphere radius, length from the sphere's far pole to the apex > 2 radius], none [], "
                   "mesh [scale]",
                   [](const Object& o) { return Value(o.body.dimensions_m); },
                   [](Object& o, const Value& v) {
                     refuse_central_body(o, "dimensions_m");
                     const auto& a = array_of(v, "dimensions_m");
                     check_dimensions(o.body.shape, a, "dimensions_m");
                     o.body.dimensions_m = a;
                   },
                   Range{object_bounds::min_length_m, max_length_m}});
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
  t.push_back(Spec{"mesh_file", ValueType::string, "",
                   "Shape mesh: the 3-D model, a glTF 2.0 (.gltf, .glb) or Wavefront OBJ (.obj) file, its triangles "
                   "scaled by dimensions_m = [scale] (metres per file unit) in the body frame; read and checked when "
                   "set (relative to the scenario's folder in a scenario, to the working directory otherwise)",
                   [](const Object& o) { return Value(o.body.mesh_file); },
                   [](Object& o, const Value& v) {
                     refuse_central_body(o, "mesh_file");
                     const std::string& file = string_of(v, "mesh_file");
                     o.body.mesh = file.empty() ? nullptr : load_mesh(file, "mesh_file");
                     o.body.mesh_file = file;
                   }});
  t.push_back(Spec{"mesh_materials", ValueType::string, "",
                   "Shape mesh: the file's materials as engine surfaces, a JSON object {\"<name in the file>\": "
                   "{material, temperature_K, reflectance}}; a material not named takes the object's",
                   [](const Object& o) { return Value(o.body.mesh_materials); },
                   [](Object& o, const Value& v) {
                     refuse_central_body(o, "mesh_materials");
                     const std::string& text = string_of(v, "mesh_materials");
                     o.body.mesh_materials_parsed = parse_mesh_materials(text, "mesh_materials");
                     o.body.mesh_materials = text;
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
      "fidelity: 785 km at the Earth's radius for central bodies, an eighth of the object's size otherwise, of "
      "its narrowest stage's diameter for a missile with missile_stages)",
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
      const auto& list = *o.body.missile_stage_list;
      if (!list.empty() && integer_of(v, "stages") != static_cast<std::int64_t>(list.size()))
        throw Error(Status::not_allowed, "stages: missile '" + o.name + "' has " + std::to_string(list.size()) +
                                             " stages in missile_stages; the count follows them");
      set_stages(o, v);
    };
    t.push_back(stages);
    t.push_back(Spec{"missile_stages", ValueType::string, "",
                     "Stages as a JSON array, first (launched) stage first (spec 4.3.6): {length_m, radius_m, parts "
                     "(composite parts in the stage frame, z = 0 at its aft end; default a cylinder), separation_s, "
                     "drawn_after_separation_s, separation_speed_m_s, plume {temperature_K or spectrum, length_scale, "
                     "width_scale, on_s, off_s}}; times from the stage's time 0 (launch, then the separation of the "
                     "stage below). \"[]\" = none: the missile is its shape. Sets stages to the count",
                     [](const Object& o) { return Value(o.body.missile_stages); },
                     [](Object& o, const Value& v) {
                       const std::string& text = string_of(v, "missile_stages");
                       auto list = std::make_shared<const std::vector<MissileStage>>(
                           parse_missile_stages(text, "missile_stages"));
                       if (!list->empty()) o.body.stages = static_cast<std::int64_t>(list->size());
                       o.body.missile_stage_list = std::move(list);
                       o.body.missile_stages = text;
                     }});
    t.push_back(Spec{"launch_time_utc", ValueType::string, "",
                     "Launch time, ISO-8601 UTC (time 0 of the first stage, spec 4.3.6); \"\" = not launched "
                     "(the stack stands whole, no plume)",
                     [](const Object& o) { return Value(o.body.launch_time_utc); },
                     [](Object& o, const Value& v) {
                       const std::string& text = string_of(v, "launch_time_utc");
                       if (text.empty()) {
                         o.body.launch_time.reset();
                       } else {
                         JulianDate utc;
                         try {
                           utc = utc_from_iso(text);
                         } catch (const Error& e) {
                           throw Error(e.status(), std::string("launch_time_utc: ") + e.what());
                         }
                         o.body.launch_time = EngineTime::from(utc, "launch_time_utc");
                       }
                       o.body.launch_time_utc = text;
                     }});
  }
  return t;
}

// Saturn's rings in its disc's brightness (radiometry/disk_photometry.hpp:
// Mallama & Hilton 2018 eq. 10): a property of every central body, true by
// default for Saturn only, and only Saturn's may be true.
Spec rings_property() {
  Spec rings = bool_property<Object>(
      "rings",
      "Saturn: its brightness as a point source and as a light includes its rings' (Mallama & Hilton 2018 eq. 10, "
      "from the ring opening seen and lit; true, the default, as observed magnitudes do); false: the globe alone "
      "(eqs. 11-12). The rings are not drawn in images",
      [](Object& o) -> auto& { return o.body.rings; });
  const auto set = rings.set;
  rings.set = [set](Object& o, const Value& v) {
    Object probe = o;
    set(probe, v);
    if (probe.body.rings && !(o.kind == ObjectKind::central_body && o.central_body == CentralBody::saturn))
      throw Error(Status::not_allowed, "rings: only Saturn's rings are modeled, not " + o.name + "'s");
    set(o, v);
  };
  return rings;
}

// The Earth's atmosphere (spec 4.3.1.1, 4.1.5.3 eq. 9): properties of every
// central body, but only the Earth's may be switched on.
std::vector<Spec> atmosphere_properties() {
  std::vector<Spec> t;
  Spec model = enum_property<Object, AtmosphereModel>(
      "atmosphere",
      "The atmosphere along every path the world traces (spec 4.3.1.1, eq. 9): none (vacuum, the default) or simple "
      "(transmission and thermal path radiance from the profile, absorbers and aerosol below; solar scatter not yet); "
      "the Earth's only",
      [](Object& o) -> auto& { return o.atmosphere.model; }, atmosphere_model_names());
  const auto set_model = model.set;
  model.set = [set_model](Object& o, const Value& v) {
    Object probe = o;
    set_model(probe, v);
    if (probe.atmosphere.model != AtmosphereModel::none &&
        !(o.kind == ObjectKind::central_body && o.central_body == CentralBody::earth))
      throw Error(Status::not_allowed,
                  "atmosphere: only the Earth's atmosphere is modeled (spec 4.3.1), not " + o.name + "'s");
    set_model(o, v);
  };
  t.push_back(model);
  t.push_back(enum_property<Object, AtmosphereProfileName>(
      "atmosphere_profile",
      "Temperature, pressure, H2O and O3 against altitude: us_standard_1976 (its equations, AFGL 1986 US-standard "
      "absorbers), or the AFGL 1986 models tropical, midlatitude_summer, midlatitude_winter, subarctic_summer, "
      "subarctic_winter (Anderson et al. 1986, AFGL-TR-86-0110)",
      [](Object& o) -> auto& { return o.atmosphere.profile; }, atmosphere_profile_names()));
  t.push_back(enum_property<Object, AerosolModel>(
      "aerosol_model",
      "Boundary-layer aerosol (Shettle and Fenn 1979): rural, urban, maritime, or none (molecules only)",
      [](Object& o) -> auto& { return o.atmosphere.aerosol; }, aerosol_model_names()));
  t.push_back(number_property<Object>(
      "visibility_km", "km",
      "Meteorological visibility: the 0.55 um extinction of the boundary-layer aerosol is 3.912 / visibility "
      "less the molecules' (Koschmieder; 23 km, the default, is a clear day)",
      [](Object& o) -> auto& { return o.atmosphere.visibility_km; }, Range{0.5, 300.0}));
  t.push_back(bool_property<Object>(
      "downwelling",
      "The sky's diffuse light on surfaces (eq. 9's DownWelling: Rayleigh and aerosol scatter, and the sky's "
      "thermal emission); off reproduces single-scatter references that carry the direct Sun only (ERRATA)",
      [](Object& o) -> auto& { return o.atmosphere.downwelling; }));
  t.push_back(bool_property<Object>(
      "airglow",
      "The night airglow: the upper atmosphere's emission from a layer 85-95 km up (O I, Na D, O2 and OH bands, "
      "a continuum; data/atmosphere/airglow_nightglow.csv), seen through the air below it; it replaces spec "
      "4.1.4's three airglow lines of the background light",
      [](Object& o) -> auto& { return o.atmosphere.airglow; }));
  t.push_back(number_property<Object>("water_vapor_scale", "-",
                                      "Multiplies the profile's water-vapour density at every altitude (its column)",
                                      [](Object& o) -> auto& { return o.atmosphere.water_vapor_scale; },
                                      Range{0.0, 10.0}));
  t.push_back(number_property<Object>("ozone_scale", "-",
                                      "Multiplies the profile's ozone density at every altitude (its column)",
                                      [](Object& o) -> auto& { return o.atmosphere.ozone_scale; }, Range{0.0, 10.0}));
  return t;
}

// The Earth's cloud layer (universe/cloud_settings.hpp): properties of every
// central body, but only the Earth's may be switched on.
std::vector<Spec> cloud_properties() {
  std::vector<Spec> t;
  Spec clouds = bool_property<Object>(
      "clouds",
      "The cloud layer (off by default): the cloud fraction of the data folder's cloud map blends a backscattering "
      "cloud top at cloud_top_altitude_km, emitting at cloud_top_temperature_K, over the surface beneath; the "
      "Earth's only",
      [](Object& o) -> auto& { return o.clouds.enabled; });
  const auto set_clouds = clouds.set;
  clouds.set = [set_clouds](Object& o, const Value& v) {
    Object probe = o;
    set_clouds(probe, v);
    if (probe.clouds.enabled && !(o.kind == ObjectKind::central_body && o.central_body == CentralBody::earth))
      throw Error(Status::not_allowed, "clouds: only the Earth's cloud layer is modeled, not " + o.name + "'s");
    set_clouds(o, v);
  };
  t.push_back(clouds);
  t.push_back(number_property<Object>(
      "cloud_top_altitude_km", "km",
      "Height of the cloud tops above the ellipsoid, where they take the Sun's light (5 km: ISCCP's mean cloud-top "
      "pressure of ~550 hPa)",
      [](Object& o) -> auto& { return o.clouds.top_altitude_km; }, Range{0.0, 20.0}));
  t.push_back(number_property<Object>(
      "cloud_top_temperature_K", "K",
      "Temperature of the cloud tops' emission (255.7 K: US Standard Atmosphere 1976 at 5 km)",
      [](Object& o) -> auto& { return o.clouds.top_temperature_K; }, Range{150.0, 320.0}));
  t.push_back(number_property<Object>(
      "cloud_reflectance", "",
      "Spectral reflectance (SRF) of the cloud tops at 0.55 um; the spectrum has the shape of the fine_snow "
      "material's (water ice: bright to 1 um, dark at 1.5 and 2 um, nearly black in the thermal infrared)",
      [](Object& o) -> auto& { return o.clouds.reflectance; }, Range{0.0, 1.0}));
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

// A site's place on the Earth (WGS84). Heights from the deepest ocean floor
// to the edge of space (100 km); longitudes as pushed geodetic states take them.
std::vector<Spec> site_properties() {
  std::vector<Spec> t;
  t.push_back(number_property<Object>("latitude_deg", "deg", "Geodetic latitude (WGS84) of the site",
                                      [](Object& o) -> auto& { return o.site.latitude_deg; }, Range{-90, 90}));
  t.push_back(number_property<Object>(
      "longitude_deg", "deg", "Longitude of the site, east positive",
      [](Object& o) -> auto& { return o.site.longitude_deg; },
      Range{-object_bounds::max_abs_longitude_deg, object_bounds::max_abs_longitude_deg}));
  t.push_back(number_property<Object>("height_m", "m", "Height of the site above the WGS84 ellipsoid",
                                      [](Object& o) -> auto& { return o.site.height_m; },
                                      Range{object_bounds::min_site_height_m, object_bounds::max_site_height_m}));
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

const std::vector<std::string>& atmosphere_model_names() {
  static const std::vector<std::string> names{"none", "simple"};
  return names;
}

const std::vector<std::string>& atmosphere_profile_names() {
  static const std::vector<std::string> names{"us_standard_1976",   "tropical",         "midlatitude_summer",
                                              "midlatitude_winter", "subarctic_summer", "subarctic_winter"};
  return names;
}

const std::vector<std::string>& aerosol_model_names() {
  static const std::vector<std::string> names{"rural", "urban", "maritime", "none"};
  return names;
}

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
  if (body.shape != ShapeKind::mesh) return {part};
  if (!body.mesh) throw Error(Status::not_allowed, "mesh_file: shape mesh needs a mesh file (none is set)");
  part.mesh_file = body.mesh_file;
  part.mesh = body.mesh;
  return split_mesh(part, body.mesh_materials_parsed);
}

const std::vector<Spec>& properties_of(ObjectKind kind) {
  static const std::vector<Spec> body = body_properties(false);
  static const std::vector<Spec> missile = body_properties(true);
  static const std::vector<Spec> stars = star_field_properties();
  static const std::vector<Spec> sensors = sensor_object_properties();
  static const std::vector<Spec> sites = site_properties();
  static const std::vector<Spec> central = [] {
    std::vector<Spec> t = body_properties(false);
    t.push_back(rings_property());
    for (Spec& s : atmosphere_properties()) t.push_back(std::move(s));
    for (Spec& s : cloud_properties()) t.push_back(std::move(s));
    return t;
  }();
  switch (kind) {
    case ObjectKind::central_body: return central;
    case ObjectKind::star_field: return stars;
    case ObjectKind::missile: return missile;
    case ObjectKind::sensor: return sensors;
    case ObjectKind::site: return sites;
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
    case ObjectKind::site: return "site";
  }
  return "?";
}

}  // namespace eoir::universe
