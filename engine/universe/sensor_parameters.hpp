// Every user parameter of one sensor model (spec 5) and the fidelity knobs of
// its scene-generator/sensor-model pair. Defaults are the Table 3 sensor of
// spec 7.6 (Valid_Sens_StaticMetrics).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/fidelity.hpp"

namespace eoir::universe {

// A (time, value) reference pair of spec 5.9 (sensitivity) or 5.10 (saturation).
struct ReferencePair {
  double integration_time_ms;
  double value;  // W/cm^2 (NEI/SEI) or W/(cm^2 sr) (NER/SER)
};

// Whether reference pairs are irradiance (NEI/SEI) or radiance (NER/SER).
enum class ApertureQuantity : int { irradiance = 0, radiance = 1 };

// Hufnagel OQF presets of spec 5.6.1.2, or a custom W_rms.
enum class ImageQuality : int { diffraction_limited = 0, negligible = 1, mild = 2, moderate = 3, custom = 4 };

struct SensorParameters {
  // Spatial (spec 5.2). The FOV and pixel counts are user inputs; the pixel
  // pitch is derived from eqs. 21-22 (Table 1 notes).
  std::int64_t horizontal_pixels = 128;
  std::int64_t vertical_pixels = 128;
  double horizontal_fov_deg = 0.5;
  double vertical_fov_deg = 0.5;
  // Spectral (spec 5.3).
  double band_low_um = 1.0;
  double band_high_um = 4.0;
  std::int64_t spectral_intervals = 10;
  // Optics (spec 5.6).
  double f_number = 3.5;
  double focal_length_cm = 147.0;
  double diffraction_wavelength_um = 2.5;
  double defocus_mm = 0.0;                    // longitudinal defocus, eqs. 36-37
  ImageQuality image_quality = ImageQuality::diffraction_limited;
  double wavefront_error_rms_waves = 0.0;     // W_rms of eq. 35 (set by the preset)
  double jitter_mrad = 0.0;                   // sigma of eq. 38
  // Radiometry (spec 5.4, 5.9-5.11).
  double integration_time_ms = 10.0;
  ApertureQuantity sensitivity_quantity = ApertureQuantity::irradiance;
  std::vector<ReferencePair> sensitivity_pairs{{10.0, 1.0e-18}};
  ApertureQuantity saturation_quantity = ApertureQuantity::irradiance;
  std::vector<ReferencePair> saturation_pairs{{10.0, 1.0e-15}};
  bool saturation_enabled = true;
  // Image chain (spec 4.1.2, 5.11).
  bool noise_enabled = true;           // dark and photon noise (eqs. 53-54)
  bool display_agc = true;             // automatic gain control (spec 4.1.2)
  std::int64_t display_gain_step = 0;  // without AGC: gain 30^step (spec 4.1.2)
  // Speed against accuracy (core/fidelity.hpp).
  Fidelity fidelity;
};

// The W_rms of each preset (data, not code: later product documentation lists
// 0.21 for "moderate"; spec ERRATA 5.6.1.2), indexed by ImageQuality.
struct ImageQualityPreset {
  const char* name;
  double wavefront_error_rms_waves;
};
const std::vector<ImageQualityPreset>& image_quality_presets();
const std::vector<std::string>& image_quality_names();  // the presets and "custom"

// Throws eoir::Error naming `field` (e.g. "sensitivity_pairs[2].value")
// unless there are 1..limits::max_reference_pairs pairs (limit_exceeded past
// it) with finite positive times and values and no repeated time.
void validate_reference_pairs(const std::vector<ReferencePair>& pairs, const std::string& field);

// The one place a sensor is validated: every parameter in its range (the
// property table's), the reference pairs, the band edges in order and the
// fidelity knobs. Throws eoir::Error naming the field.
void validate(const SensorParameters& p);

}  // namespace eoir::universe
