// Every user parameter of one sensor model (spec 5). Defaults are the Table 3
// sensor of spec 7.6 (Valid_Sens_StaticMetrics).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace eoir::sensor {

// A (time, value) reference pair of spec 5.9 (sensitivity) or 5.10 (saturation).
struct ReferencePair {
  double integration_time_ms;
  double value;  // W/cm^2 (NEI/SEI) or W/(cm^2 sr) (NER/SER)
};

// Whether reference pairs are irradiance (NEI/SEI) or radiance (NER/SER).
enum class ApertureQuantity { irradiance, radiance };

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
  double defocus_mm = 0.0;                   // longitudinal defocus, eqs. 36-37
  std::string image_quality = "diffraction_limited";  // preset name or "custom"
  double wavefront_error_rms_waves = 0.0;    // W_rms of eq. 35 (set by the preset)
  double jitter_mrad = 0.0;                  // sigma of eq. 38
  // Radiometry (spec 5.4, 5.9-5.11).
  double integration_time_ms = 10.0;
  ApertureQuantity sensitivity_quantity = ApertureQuantity::irradiance;
  std::vector<ReferencePair> sensitivity_pairs{{10.0, 1.0e-18}};
  ApertureQuantity saturation_quantity = ApertureQuantity::irradiance;
  std::vector<ReferencePair> saturation_pairs{{10.0, 1.0e-15}};
  bool saturation_enabled = true;
  // Fidelity knobs (DESIGN.md section 4).
  std::int64_t psf_grid_size = 512;    // FFT grid of the PSF (eq. 40), power of two
  std::int64_t otf_curve_points = 101; // samples of the OTF/MTF report curves
  // Image chain (spec 4.2, 4.1.2, 5.11).
  std::string scene_mode = "coarse";       // "coarse" (4.2.1) or "smooth" (4.2.2)
  std::string band_integration = "grid";   // "grid" (spec 5.3 intervals) or "exact" (Planck series)
  bool noise_enabled = true;               // dark and photon noise (eqs. 53-54)
  bool display_agc = true;                 // automatic gain control (spec 4.1.2)
  std::int64_t display_gain_step = 0;      // without AGC: gain 30^step (spec 4.1.2)
};

// Hufnagel OQF presets of spec 5.6.1.2 (data, not code: ERRATA 5.6.1.2).
struct ImageQualityPreset {
  const char* name;
  double wavefront_error_rms_waves;
};
const std::vector<ImageQualityPreset>& image_quality_presets();

}  // namespace eoir::sensor
