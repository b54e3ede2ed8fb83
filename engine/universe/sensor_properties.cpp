#include "universe/sensor_properties.hpp"

#include <string>

#include "core/error.hpp"

namespace eoir::universe {
namespace {
using P = SensorParameters;
using Spec = PropertySpec<P>;

const std::vector<std::string>& quantity_names() {
  static const std::vector<std::string> names{"irradiance", "radiance"};
  return names;
}

Value flatten(const std::vector<ReferencePair>& pairs) {
  std::vector<double> out;
  for (const auto& p : pairs) {
    out.push_back(p.integration_time_ms);
    out.push_back(p.value);
  }
  return out;
}

// Flattened (integration_time_ms, value) pairs, checked by
// validate_reference_pairs (spec 5.9-5.10).
std::vector<ReferencePair> parse_pairs(const Value& v, const std::string& field) {
  const auto& a = array_of(v, field);
  if (a.size() % 2 != 0)
    throw Error(Status::out_of_range, field + ": expects flattened (integration_time_ms, value) pairs, got " +
                                          std::to_string(a.size()) + " numbers");
  std::vector<ReferencePair> pairs;
  for (size_t i = 0; i < a.size(); i += 2) pairs.push_back({a[i], a[i + 1]});
  validate_reference_pairs(pairs, field);
  return pairs;
}

Spec pairs_property(const char* name, const char* description, std::vector<ReferencePair> P::*member) {
  return Spec{name, ValueType::array, "ms, W/cm^2 or W/(cm^2 sr)", description,
              [member](const P& p) { return flatten(p.*member); },
              [name, member](P& p, const Value& v) { p.*member = parse_pairs(v, name); },
              Range{sensor_bounds::min_reference_value, sensor_bounds::max_reference_value}};
}
}  // namespace

const std::vector<Spec>& sensor_properties() {
  static const std::vector<Spec> table = [] {
    std::vector<Spec> t;
    const Range fov_range{sensor_bounds::min_fov_deg, sensor_bounds::max_fov_deg};
    const Range band_range{sensor_bounds::min_band_um, sensor_bounds::max_band_um};
    t.push_back(integer_property<P>("horizontal_pixels", "count",
                                    "Number of pixels in the horizontal direction (spec 5.2)",
                                    [](P& p) -> auto& { return p.horizontal_pixels; }, Range{0, 16384, true}));
    t.push_back(integer_property<P>("vertical_pixels", "count", "Number of pixels in the vertical direction (spec 5.2)",
                                    [](P& p) -> auto& { return p.vertical_pixels; }, Range{0, 16384, true}));
    t.push_back(number_property<P>("horizontal_fov_deg", "deg", "Full-angle horizontal field of view (eq. 21)",
                                   [](P& p) -> auto& { return p.horizontal_fov_deg; }, fov_range));
    t.push_back(number_property<P>("vertical_fov_deg", "deg", "Full-angle vertical field of view (eq. 22)",
                                   [](P& p) -> auto& { return p.vertical_fov_deg; }, fov_range));
    t.push_back(number_property<P>("band_low_um", "um", "Low band edge wavelength (spec 5.3; 0.28-28 um, spec 4.1.1)",
                                   [](P& p) -> auto& { return p.band_low_um; }, band_range));
    t.push_back(number_property<P>("band_high_um", "um", "High band edge wavelength (spec 5.3; 0.28-28 um)",
                                   [](P& p) -> auto& { return p.band_high_um; }, band_range));
    t.push_back(integer_property<P>("spectral_intervals", "count", "Number of spectral intervals N (spec 5.3)",
                                    [](P& p) -> auto& { return p.spectral_intervals; }, Range{1, 100000}));
    t.push_back(number_property<P>("f_number", "", "F-number F/# (spec 5.4)", [](P& p) -> auto& { return p.f_number; },
                                   Range{sensor_bounds::min_f_number, sensor_bounds::max_f_number}));
    t.push_back(number_property<P>("focal_length_cm", "cm", "Effective focal length f (spec 5.2)",
                                   [](P& p) -> auto& { return p.focal_length_cm; },
                                   Range{sensor_bounds::min_focal_length_cm, sensor_bounds::max_focal_length_cm}));
    t.push_back(number_property<P>("diffraction_wavelength_um", "um", "Diffraction wavelength lambda_diff (eq. 34)",
                                   [](P& p) -> auto& { return p.diffraction_wavelength_um; },
                                   Range{sensor_bounds::min_diffraction_wavelength_um,
                                         sensor_bounds::max_diffraction_wavelength_um}));
    t.push_back(number_property<P>("defocus_mm", "mm", "Longitudinal defocus delta (eqs. 36-37)",
                                   [](P& p) -> auto& { return p.defocus_mm; }, Range{0, 1e4}));
    Spec quality = enum_property<P, ImageQuality>(
        "image_quality",
        "Hufnagel aberration preset (spec 5.6.1.2): diffraction_limited, negligible, mild, moderate, or custom "
        "(keeps wavefront_error_rms_waves)",
        [](P& p) -> auto& { return p.image_quality; }, image_quality_names());
    const auto set_quality = quality.set;
    quality.set = [set_quality](P& p, const Value& v) {
      set_quality(p, v);
      if (p.image_quality != ImageQuality::custom)
        p.wavefront_error_rms_waves =
            image_quality_presets()[static_cast<std::size_t>(p.image_quality)].wavefront_error_rms_waves;
    };
    t.push_back(quality);
    Spec wrms = number_property<P>(
        "wavefront_error_rms_waves", "waves",
        "RMS wavefront error W_rms of the Hufnagel OQF (eq. 35); setting it makes image_quality custom",
        [](P& p) -> auto& { return p.wavefront_error_rms_waves; }, Range{0, 10});
    const auto set_wrms = wrms.set;
    wrms.set = [set_wrms](P& p, const Value& v) {
      set_wrms(p, v);
      // The preset stays if this is its own W_rms (a state applies
      // image_quality, then W_rms): a custom W_rms equal to a preset's
      // stays custom, so that states load as they were saved (issue 25).
      const auto& presets = image_quality_presets();
      const auto q = static_cast<std::size_t>(p.image_quality);
      if (q >= presets.size() || presets[q].wavefront_error_rms_waves != p.wavefront_error_rms_waves)
        p.image_quality = ImageQuality::custom;
    };
    t.push_back(wrms);
    t.push_back(number_property<P>("jitter_mrad", "mrad", "RMS line-of-sight jitter sigma (eq. 38)",
                                   [](P& p) -> auto& { return p.jitter_mrad; }, Range{0, 1e3}));
    t.push_back(number_property<P>("integration_time_ms", "ms", "Integration time t_i (eq. 31)",
                                   [](P& p) -> auto& { return p.integration_time_ms; },
                                   Range{sensor_bounds::min_integration_time_ms, sensor_bounds::max_integration_time_ms}));
    t.push_back(enum_property<P, ApertureQuantity>(
        "sensitivity_quantity", "Whether sensitivity_pairs hold NEI (irradiance, W/cm^2) or NER (radiance, W/(cm^2 sr))",
        [](P& p) -> auto& { return p.sensitivity_quantity; }, quantity_names()));
    t.push_back(pairs_property("sensitivity_pairs",
                               "Sensitivity reference pairs (spec 5.9), flattened: t1, NEI1, t2, NEI2, ... (1 to 8 pairs)",
                               &P::sensitivity_pairs));
    t.push_back(enum_property<P, ApertureQuantity>("saturation_quantity",
                                                   "Whether saturation_pairs hold SEI (irradiance) or SER (radiance)",
                                                   [](P& p) -> auto& { return p.saturation_quantity; },
                                                   quantity_names()));
    t.push_back(pairs_property("saturation_pairs",
                               "Saturation reference pairs (spec 5.10), flattened: t1, SEI1, ... (1 to 8 pairs)",
                               &P::saturation_pairs));
    t.push_back(bool_property<P>("saturation_enabled", "Simulate saturation (spec 5.11.5)",
                                 [](P& p) -> auto& { return p.saturation_enabled; }));
    t.push_back(bool_property<P>("noise_enabled", "Add dark and scene photon noise to the sensor image (eqs. 53-55)",
                                 [](P& p) -> auto& { return p.noise_enabled; }));
    t.push_back(bool_property<P>("display_agc", "Automatic gain control of the display images (spec 4.1.2)",
                                 [](P& p) -> auto& { return p.display_agc; }));
    t.push_back(integer_property<P>("display_gain_step", "count",
                                    "Display gain without AGC: each step multiplies the gain by 30 (spec 4.1.2); step "
                                    "0 maps the saturation level (sensor) or 1e-6 W/cm^2 (scene) to 255",
                                    [](P& p) -> auto& { return p.display_gain_step; }, Range{-10, 10}));
    t.push_back(enum_property<P, DisplayStretch>(
        "display_stretch",
        "Display stretch of both display images (issue 21): linear, log, asinh (of the AGC or gain range), or "
        "zscale (IRAF's automatic limits, linear); saturated pixels show white",
        [](P& p) -> auto& { return p.display_stretch; }, display_stretch_names()));
    // The optional detector stage after eq. 55 (sensor/detector.hpp; beyond spec 5).
    namespace b = sensor_bounds;
    t.push_back(bool_property<P>("detector_model",
                                 "Detector stage after eq. 55: Poisson photon and dark noise, PRNU, DSNU, hot and dead "
                                 "pixels, full well, read noise, gain, bias and ADC (ADU image); off keeps the spec's "
                                 "Gaussian noise (eqs. 53-55)",
                                 [](P& p) -> auto& { return p.detector.enabled; }));
    t.push_back(number_property<P>("dark_current_e_s", "e-/s", "Detector: mean dark current per pixel",
                                   [](P& p) -> auto& { return p.detector.dark_current_e_s; },
                                   Range{0, b::max_dark_current_e_s}));
    t.push_back(number_property<P>("bias_adu", "ADU", "Detector: bias (offset) added before the ADC",
                                   [](P& p) -> auto& { return p.detector.bias_adu; }, Range{0, 4294967295.0}));
    t.push_back(number_property<P>("gain_e_per_adu", "e-/ADU", "Detector: conversion gain",
                                   [](P& p) -> auto& { return p.detector.gain_e_per_adu; },
                                   Range{b::min_gain_e_per_adu, b::max_gain_e_per_adu}));
    t.push_back(number_property<P>("read_noise_e", "e-", "Detector: read noise sigma (Gaussian)",
                                   [](P& p) -> auto& { return p.detector.read_noise_e; },
                                   Range{0, b::max_read_noise_e}));
    t.push_back(number_property<P>("full_well_e", "e-", "Detector: full-well capacity (charge clips here)",
                                   [](P& p) -> auto& { return p.detector.full_well_e; },
                                   Range{0, b::max_full_well_e, true}));
    t.push_back(integer_property<P>("adc_bits", "bits", "Detector: ADC bit depth (ADU clip at 2^bits - 1)",
                                    [](P& p) -> auto& { return p.detector.adc_bits; },
                                    Range{static_cast<double>(b::min_adc_bits), static_cast<double>(b::max_adc_bits)}));
    t.push_back(number_property<P>("prnu_fraction", "", "Detector: pixel response non-uniformity, relative sigma",
                                   [](P& p) -> auto& { return p.detector.prnu_fraction; }, Range{0, 1}));
    t.push_back(number_property<P>("dsnu_e_s", "e-/s", "Detector: dark-signal non-uniformity, sigma of the dark current",
                                   [](P& p) -> auto& { return p.detector.dsnu_e_s; },
                                   Range{0, b::max_dark_current_e_s}));
    t.push_back(number_property<P>("hot_pixel_fraction", "", "Detector: fraction of hot pixels",
                                   [](P& p) -> auto& { return p.detector.hot_pixel_fraction; }, Range{0, 1}));
    t.push_back(number_property<P>("hot_pixel_dark_current_e_s", "e-/s", "Detector: dark current of a hot pixel",
                                   [](P& p) -> auto& { return p.detector.hot_pixel_dark_current_e_s; },
                                   Range{0, b::max_dark_current_e_s}));
    t.push_back(number_property<P>("dead_pixel_fraction", "", "Detector: fraction of dead pixels (no photo response)",
                                   [](P& p) -> auto& { return p.detector.dead_pixel_fraction; }, Range{0, 1}));
    t.push_back(integer_property<P>("detector_pattern_seed", "",
                                    "Detector: seed of the fixed pattern (PRNU, DSNU, hot and dead pixels)",
                                    [](P& p) -> auto& { return p.detector.pattern_seed; },
                                    Range{0, 9007199254740992.0}));
    // Resolved objects moving during the integration (scene/motion_substeps.hpp).
    t.push_back(integer_property<P>(
        "motion_substeps", "count",
        "Time sub-steps over the integration for objects imaged as extended sources: the scene is the mean of this "
        "many scenes at the sub-step times, so a resolved object that moves smears; 1 keeps spec 5.1 assumption 6 "
        "(the scene at the frame time)",
        [](P& p) -> auto& { return p.motion_substeps; },
        Range{1, static_cast<double>(sensor_bounds::max_motion_substeps)}));
    // The fidelity knobs, as properties of the sensor whose pair they tune.
    for (const PropertySpec<Fidelity>& k : fidelity_properties()) {
      const auto get = k.get;
      const auto set = k.set;
      t.push_back(Spec{k.name, k.type, k.unit, k.description, [get](const P& p) { return get(p.fidelity); },
                       [set](P& p, const Value& v) { set(p.fidelity, v); }, k.range, k.choices, true});
    }
    return t;
  }();
  return table;
}

}  // namespace eoir::universe
