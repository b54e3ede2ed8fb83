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

// Physical bounds of the sensor parameters: each keeps every derived quantity
// (IFOV, pitch, responsivities, noise, the PSF grid) finite and the cost of a
// frame bounded; sensor_properties.cpp and schemas/sensor.schema.json use them.
namespace sensor_bounds {
// Full field of view: 1e-6 deg (3.6 mas, below any imaging sensor's field):
// with 16384 pixels of 16 samples a sample still spans ~1e3 ulp of a unit
// direction in double, so neighbouring rays stay distinct.
constexpr double min_fov_deg = 1.0e-6;
constexpr double max_fov_deg = 179.9;
// F/# >= 0.5: the limit of an aplanatic lens in vacuum (F/# = 1 / (2 NA), NA <= 1).
constexpr double min_f_number = 0.5;
constexpr double max_f_number = 1000.0;
// 10 um to 10 km: below the focal length of any lens, above the largest telescopes.
constexpr double min_focal_length_cm = 1.0e-3;
constexpr double max_focal_length_cm = 1.0e6;
// The wavelengths the engine models (spec 4.1.1): sensor bands lie within
// them, material tables cover them.
constexpr double min_band_um = 0.28;
constexpr double max_band_um = 28.0;
// lambda_diff: from the shortest wavelength the engine models.
constexpr double min_diffraction_wavelength_um = min_band_um;
constexpr double max_diffraction_wavelength_um = 1000.0;
// Integration times (and reference-pair times): 1 ns to 10^4 s.
constexpr double min_integration_time_ms = 1.0e-6;
constexpr double max_integration_time_ms = 1.0e7;
constexpr std::int64_t max_motion_substeps = 64;
// NEI/SEI (W/cm^2) and NER/SER (W/(cm^2 sr)) of reference pairs: 1e-40 to
// 1e10, decades beyond any detector (the Sun gives 0.14 W/cm^2 and
// 2e3 W/(cm^2 sr)) yet squares (noise variances) stay finite.
constexpr double min_reference_value = 1.0e-40;
constexpr double max_reference_value = 1.0e10;
// A pixel spans at most 1e4 diffraction widths lambda_diff F# (its IFOV at
// most 1e4 lambda / D): the energy on detector (eq. 40) folds the OTF onto
// the pixel grid at a cost growing with the square of that ratio (about 3 s
// at 1e4, hours at 1e6). Checked when the sensor is evaluated.
constexpr double max_pitch_diffraction_widths = 1.0e4;
// The detector stage (sensor/detector.hpp): a full well of up to 1e9
// electrons (beyond any CCD or CMOS well), ADCs of 1 to 32 bits (the ADU
// image is unsigned 32-bit), a gain of 1e-6 to 1e6 e-/ADU.
constexpr double max_full_well_e = 1.0e9;
constexpr double min_gain_e_per_adu = 1.0e-6;
constexpr double max_gain_e_per_adu = 1.0e6;
constexpr std::int64_t min_adc_bits = 1;
constexpr std::int64_t max_adc_bits = 32;
constexpr double max_dark_current_e_s = 1.0e9;
constexpr double max_read_noise_e = 1.0e6;
}  // namespace sensor_bounds

// Whether reference pairs are irradiance (NEI/SEI) or radiance (NER/SER).
enum class ApertureQuantity : int { irradiance = 0, radiance = 1 };

// How display images map values to bytes (sensor/display.hpp; issue 21 item 6).
enum class DisplayStretch : int { linear = 0, log = 1, asinh = 2, zscale = 3 };
const std::vector<std::string>& display_stretch_names();  // "linear", "log", "asinh", "zscale"

// The optional detector stage after eq. 55 (beyond spec 5; sensor/detector.hpp).
// Off by default: the spec's Gaussian noise and saturation level stay.
struct DetectorParameters {
  bool enabled = false;                   // detector_model
  double dark_current_e_s = 0.0;          // mean dark current per pixel, e-/s
  double bias_adu = 1000.0;               // offset added before the ADC, ADU
  double gain_e_per_adu = 1.0;            // conversion gain, e-/ADU
  double read_noise_e = 0.0;              // read noise sigma, e-
  double full_well_e = 1.0e5;             // full-well capacity, e-
  std::int64_t adc_bits = 16;             // ADC bit depth: ADU in [0, 2^bits - 1]
  double prnu_fraction = 0.0;             // pixel response non-uniformity, relative sigma
  double dsnu_e_s = 0.0;                  // dark-signal non-uniformity, sigma of the dark current, e-/s
  double hot_pixel_fraction = 0.0;        // fraction of pixels with hot_pixel_dark_current_e_s
  double hot_pixel_dark_current_e_s = 1.0e4;
  double dead_pixel_fraction = 0.0;       // fraction of pixels with no photo response
  std::int64_t pattern_seed = 1;          // seed of the fixed pattern (PRNU, DSNU, hot and dead pixels)
};

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
  // Time sub-steps of the scene over the integration for resolved objects
  // (scene/motion_substeps.hpp; beyond spec 5.1 assumption 6, which 1 keeps).
  std::int64_t motion_substeps = 1;
  ApertureQuantity sensitivity_quantity = ApertureQuantity::irradiance;
  std::vector<ReferencePair> sensitivity_pairs{{10.0, 1.0e-18}};
  ApertureQuantity saturation_quantity = ApertureQuantity::irradiance;
  std::vector<ReferencePair> saturation_pairs{{10.0, 1.0e-15}};
  bool saturation_enabled = true;
  // Image chain (spec 4.1.2, 5.11).
  bool noise_enabled = true;           // dark and photon noise (eqs. 53-54)
  bool display_agc = true;             // automatic gain control (spec 4.1.2)
  std::int64_t display_gain_step = 0;  // without AGC: gain 30^step (spec 4.1.2)
  DisplayStretch display_stretch = DisplayStretch::linear;
  DetectorParameters detector;
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
// it) with times and values within sensor_bounds and no repeated time.
void validate_reference_pairs(const std::vector<ReferencePair>& pairs, const std::string& field);

// The one place a sensor is validated: every parameter in its range (the
// property table's), the reference pairs, the band edges in order, the pixel
// pitch against the diffraction width and the fidelity knobs. Throws
// eoir::Error naming the field.
void validate(const SensorParameters& p);

}  // namespace eoir::universe
