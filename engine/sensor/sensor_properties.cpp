#include "sensor/sensor_properties.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/limits.hpp"

namespace eoir::sensor {
namespace {
using P = SensorParameters;
using Spec = PropertySpec<P>;

double as_number(const Value& v, const char* field) {
  if (auto d = std::get_if<double>(&v)) return *d;
  if (auto i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  throw Error(Status::type_mismatch, std::string(field) + ": expects a number");
}
std::int64_t as_integer(const Value& v, const char* field) {
  if (auto i = std::get_if<std::int64_t>(&v)) return *i;
  if (auto d = std::get_if<double>(&v)) {
    if (std::isfinite(*d) && std::floor(*d) == *d && std::fabs(*d) < 9e15) return static_cast<std::int64_t>(*d);
    throw Error(Status::out_of_range, std::string(field) + ": expects a whole number, got " + std::to_string(*d));
  }
  throw Error(Status::type_mismatch, std::string(field) + ": expects an integer");
}
const std::string& as_string(const Value& v, const char* field) {
  if (auto s = std::get_if<std::string>(&v)) return *s;
  throw Error(Status::type_mismatch, std::string(field) + ": expects a string");
}
bool as_bool(const Value& v, const char* field) {
  if (auto b = std::get_if<bool>(&v)) return *b;
  throw Error(Status::type_mismatch, std::string(field) + ": expects a bool");
}
const std::vector<double>& as_array(const Value& v, const char* field) {
  if (auto a = std::get_if<std::vector<double>>(&v)) return *a;
  throw Error(Status::type_mismatch, std::string(field) + ": expects an array of numbers");
}

void check_range(double v, double lo, double hi, const char* field, const char* unit) {
  require_finite(v, field);
  if (v < lo || v > hi)
    throw Error(Status::out_of_range, std::string(field) + ": must be in [" + std::to_string(lo) + ", " +
                                          std::to_string(hi) + "] " + unit + ", got " + std::to_string(v));
}

Spec number(const char* name, const char* unit, const char* description, double P::*member, double lo, double hi,
            bool open_low) {
  return Spec{name, ValueType::number, unit, description, [member](const P& p) { return Value(p.*member); },
              [=](P& p, const Value& v) {
                const double x = as_number(v, name);
                if (open_low) require_positive(x, name);
                check_range(x, lo, hi, name, unit);
                p.*member = x;
              }};
}

Spec integer(const char* name, const char* unit, const char* description, std::int64_t P::*member,
             std::int64_t lo, std::int64_t hi) {
  return Spec{name, ValueType::integer, unit, description, [member](const P& p) { return Value(p.*member); },
              [=](P& p, const Value& v) {
                const std::int64_t x = as_integer(v, name);
                if (x < lo || x > hi)
                  throw Error(Status::out_of_range, std::string(name) + ": must be in [" + std::to_string(lo) +
                                                        ", " + std::to_string(hi) + "], got " + std::to_string(x));
                p.*member = x;
              }};
}

Spec choice(const char* name, const char* description, std::string P::*member, std::vector<std::string> options) {
  return Spec{name, ValueType::string, "", description, [member](const P& p) { return Value(p.*member); },
              [=](P& p, const Value& v) {
                const std::string& s = as_string(v, name);
                std::string list;
                for (const auto& o : options) {
                  if (s == o) {
                    p.*member = s;
                    return;
                  }
                  list += (list.empty() ? "" : ", ") + o;
                }
                throw Error(Status::unknown_name, std::string(name) + ": unknown value '" + s + "' (" + list + ")");
              }};
}

Spec flag(const char* name, const char* description, bool P::*member) {
  return Spec{name, ValueType::boolean, "", description, [member](const P& p) { return Value(p.*member); },
              [=](P& p, const Value& v) { p.*member = as_bool(v, name); }};
}

const char* quantity_name(ApertureQuantity q) { return q == ApertureQuantity::irradiance ? "irradiance" : "radiance"; }
ApertureQuantity parse_quantity(const Value& v, const char* field) {
  const std::string& s = as_string(v, field);
  if (s == "irradiance") return ApertureQuantity::irradiance;
  if (s == "radiance") return ApertureQuantity::radiance;
  throw Error(Status::unknown_name, std::string(field) + ": unknown quantity '" + s + "' (irradiance or radiance)");
}

Value flatten(const std::vector<ReferencePair>& pairs) {
  std::vector<double> out;
  for (const auto& p : pairs) {
    out.push_back(p.integration_time_ms);
    out.push_back(p.value);
  }
  return out;
}
std::vector<ReferencePair> parse_pairs(const Value& v, const char* field) {
  const auto& a = as_array(v, field);
  if (a.empty() || a.size() % 2 != 0)
    throw Error(Status::out_of_range, std::string(field) +
                                          ": expects flattened (integration_time_ms, value) pairs, got " +
                                          std::to_string(a.size()) + " numbers");
  if (a.size() / 2 > limits::max_reference_pairs)
    throw Error(Status::limit_exceeded, std::string(field) + ": at most " +
                                            std::to_string(limits::max_reference_pairs) + " reference pairs, got " +
                                            std::to_string(a.size() / 2));
  std::vector<ReferencePair> pairs;
  for (size_t i = 0; i < a.size(); i += 2) {
    const std::string at = std::string(field) + "[" + std::to_string(i / 2) + "]";
    require_positive(a[i], at + ".integration_time_ms");
    require_positive(a[i + 1], at + ".value");
    for (const auto& q : pairs)
      if (q.integration_time_ms == a[i])
        throw Error(Status::out_of_range, at + ".integration_time_ms: duplicate time " + std::to_string(a[i]));
    pairs.push_back({a[i], a[i + 1]});
  }
  return pairs;
}
}  // namespace

const std::vector<Spec>& sensor_properties() {
  static const std::vector<Spec> table = [] {
    std::vector<Spec> t;
    t.push_back(integer("horizontal_pixels", "count", "Number of pixels in the horizontal direction (spec 5.2)",
                        &P::horizontal_pixels, 1, 16384));
    t.push_back(integer("vertical_pixels", "count", "Number of pixels in the vertical direction (spec 5.2)",
                        &P::vertical_pixels, 1, 16384));
    t.push_back(number("horizontal_fov_deg", "deg", "Full-angle horizontal field of view (eq. 21)",
                       &P::horizontal_fov_deg, 0, 179.9, true));
    t.push_back(number("vertical_fov_deg", "deg", "Full-angle vertical field of view (eq. 22)",
                       &P::vertical_fov_deg, 0, 179.9, true));
    t.push_back(number("band_low_um", "um", "Low band edge wavelength (spec 5.3; 0.28-28 um, spec 4.1.1)",
                       &P::band_low_um, 0.28, 28.0, true));
    t.push_back(number("band_high_um", "um", "High band edge wavelength (spec 5.3; 0.28-28 um)", &P::band_high_um,
                       0.28, 28.0, true));
    t.push_back(integer("spectral_intervals", "count", "Number of spectral intervals N (spec 5.3)",
                        &P::spectral_intervals, 1, 100000));
    t.push_back(number("f_number", "", "F-number F/# (spec 5.4)", &P::f_number, 0, 1000, true));
    t.push_back(number("focal_length_cm", "cm", "Effective focal length f (spec 5.2)", &P::focal_length_cm, 0, 1e6,
                       true));
    t.push_back(number("diffraction_wavelength_um", "um", "Diffraction wavelength lambda_diff (eq. 34)",
                       &P::diffraction_wavelength_um, 0, 1000, true));
    t.push_back(number("defocus_mm", "mm", "Longitudinal defocus delta (eqs. 36-37)", &P::defocus_mm, 0, 1e4, false));
    t.push_back(Spec{"image_quality", ValueType::string, "",
                     "Hufnagel aberration preset (spec 5.6.1.2): diffraction_limited, negligible, mild, moderate, or "
                     "custom (keeps wavefront_error_rms_waves)",
                     [](const P& p) { return Value(p.image_quality); },
                     [](P& p, const Value& v) {
                       const std::string& s = as_string(v, "image_quality");
                       if (s == "custom") {
                         p.image_quality = s;
                         return;
                       }
                       std::string list;
                       for (const auto& preset : image_quality_presets()) {
                         if (s == preset.name) {
                           p.image_quality = s;
                           p.wavefront_error_rms_waves = preset.wavefront_error_rms_waves;
                           return;
                         }
                         list += std::string(list.empty() ? "" : ", ") + preset.name;
                       }
                       throw Error(Status::unknown_name,
                                   "image_quality: unknown preset '" + s + "' (known: " + list + ", custom)");
                     }});
    t.push_back(Spec{"wavefront_error_rms_waves", ValueType::number, "waves",
                     "RMS wavefront error W_rms of the Hufnagel OQF (eq. 35); setting it makes image_quality custom",
                     [](const P& p) { return Value(p.wavefront_error_rms_waves); },
                     [](P& p, const Value& v) {
                       const double x = as_number(v, "wavefront_error_rms_waves");
                       check_range(x, 0, 10, "wavefront_error_rms_waves", "waves");
                       p.wavefront_error_rms_waves = x;
                       p.image_quality = "custom";
                       for (const auto& preset : image_quality_presets())
                         if (preset.wavefront_error_rms_waves == x) p.image_quality = preset.name;
                     }});
    t.push_back(number("jitter_mrad", "mrad", "RMS line-of-sight jitter sigma (eq. 38)", &P::jitter_mrad, 0, 1e3,
                       false));
    t.push_back(number("integration_time_ms", "ms", "Integration time t_i (eq. 31)", &P::integration_time_ms, 0, 1e7,
                       true));
    t.push_back(Spec{"sensitivity_quantity", ValueType::string, "",
                     "Whether sensitivity_pairs hold NEI (irradiance, W/cm^2) or NER (radiance, W/(cm^2 sr))",
                     [](const P& p) { return Value(std::string(quantity_name(p.sensitivity_quantity))); },
                     [](P& p, const Value& v) { p.sensitivity_quantity = parse_quantity(v, "sensitivity_quantity"); }});
    t.push_back(Spec{"sensitivity_pairs", ValueType::array, "ms, W/cm^2 or W/(cm^2 sr)",
                     "Sensitivity reference pairs (spec 5.9), flattened: t1, NEI1, t2, NEI2, ... (1 to 8 pairs)",
                     [](const P& p) { return flatten(p.sensitivity_pairs); },
                     [](P& p, const Value& v) { p.sensitivity_pairs = parse_pairs(v, "sensitivity_pairs"); }});
    t.push_back(Spec{"saturation_quantity", ValueType::string, "",
                     "Whether saturation_pairs hold SEI (irradiance) or SER (radiance)",
                     [](const P& p) { return Value(std::string(quantity_name(p.saturation_quantity))); },
                     [](P& p, const Value& v) { p.saturation_quantity = parse_quantity(v, "saturation_quantity"); }});
    t.push_back(Spec{"saturation_pairs", ValueType::array, "ms, W/cm^2 or W/(cm^2 sr)",
                     "Saturation reference pairs (spec 5.10), flattened: t1, SEI1, ... (1 to 8 pairs)",
                     [](const P& p) { return flatten(p.saturation_pairs); },
                     [](P& p, const Value& v) { p.saturation_pairs = parse_pairs(v, "saturation_pairs"); }});
    t.push_back(Spec{"saturation_enabled", ValueType::boolean, "", "Simulate saturation (spec 5.11.5)",
                     [](const P& p) { return Value(p.saturation_enabled); },
                     [](P& p, const Value& v) { p.saturation_enabled = as_bool(v, "saturation_enabled"); }});
    t.push_back(Spec{"psf_grid_size", ValueType::integer, "count",
                     "FFT grid size of the system PSF (eq. 40): a power of two, 64-4096 (fidelity knob)",
                     [](const P& p) { return Value(p.psf_grid_size); },
                     [](P& p, const Value& v) {
                       const std::int64_t n = as_integer(v, "psf_grid_size");
                       if (n < 64 || n > 4096 || (n & (n - 1)) != 0)
                         throw Error(Status::out_of_range,
                                     "psf_grid_size: must be a power of two in [64, 4096], got " + std::to_string(n));
                       p.psf_grid_size = n;
                     }});
    t.push_back(integer("otf_curve_points", "count", "Samples of the OTF and MTF report curves", &P::otf_curve_points,
                        2, 100000));
    t.push_back(choice("scene_mode", "Scene generation mode (spec 4.2): coarse (one radiance per patch dA) or "
                       "smooth (radiance evaluated at each sample's own surface point)",
                       &P::scene_mode, {"coarse", "smooth"}));
    t.push_back(choice("band_integration", "Band integration (eq. 48): grid (the spec 5.3 intervals, midpoint "
                       "rule) or exact (series integral of Planck terms, independent of the interval count)",
                       &P::band_integration, {"grid", "exact"}));
    t.push_back(flag("noise_enabled", "Add dark and scene photon noise to the sensor image (eqs. 53-55)",
                     &P::noise_enabled));
    t.push_back(flag("display_agc", "Automatic gain control of the display images (spec 4.1.2)", &P::display_agc));
    t.push_back(integer("display_gain_step", "count",
                        "Display gain without AGC: each step multiplies the gain by 30 (spec 4.1.2); step 0 maps "
                        "the saturation level (sensor) or 1e-6 W/cm^2 (scene) to 255",
                        &P::display_gain_step, -10, 10));
    return t;
  }();
  return table;
}

void check_consistency(const SensorParameters& p) {
  if (!(p.band_high_um > p.band_low_um))
    throw Error(Status::out_of_range, "band_low_um, band_high_um: band edges reversed or equal (low " +
                                          std::to_string(p.band_low_um) + " um >= high " +
                                          std::to_string(p.band_high_um) + " um)");
}

}  // namespace eoir::sensor
