// The sensor's static metrics (spec 5.12, Table 1): everything that depends
// on the sensor parameters alone. Computed once per parameter change.
#pragma once
#include <cstdint>
#include <vector>

#include "universe/sensor_parameters.hpp"

namespace eoir::sensor {

using universe::ApertureQuantity;
using universe::ReferencePair;
using universe::SensorParameters;

// A transfer-function curve against spatial frequency in object space.
struct Curve {
  std::vector<double> frequency_cycles_per_mrad;
  std::vector<double> value;
};

struct StaticMetrics {
  // Derived geometry (eqs. 13-24).
  double pixel_pitch_x_cm = 0, pixel_pitch_y_cm = 0;
  // EOIR Sensor Spatial Performance
  std::int64_t horizontal_pixels = 0, vertical_pixels = 0;
  double horizontal_fov_deg = 0, vertical_fov_deg = 0;
  double fov_solid_angle_sr = 0;
  double horizontal_ifov_mrad = 0, vertical_ifov_mrad = 0;
  double ifov_solid_angle_sr = 0;
  double effective_horizontal_fov_deg = 0, effective_vertical_fov_deg = 0;
  double effective_fov_solid_angle_sr = 0;
  double effective_horizontal_ifov_mrad = 0, effective_vertical_ifov_mrad = 0;
  double effective_ifov_solid_angle_sr = 0;
  // EOIR Sensor Spectral Performance
  double band_low_um = 0, band_high_um = 0;
  std::int64_t spectral_intervals = 0;
  // EOIR Radiometric Performance
  double integration_time_ms = 0;
  double peak_radiance_responsivity = 0;    // e-/(W/(cm^2 sr)), eq. 31
  double peak_irradiance_responsivity = 0;  // e-/(W/cm^2), eq. 32
  double dark_nei_W_cm2 = 0, dark_ner_W_cm2_sr = 0;  // eqs. 43-44
  double sei_W_cm2 = 0, ser_W_cm2_sr = 0;            // eqs. 45-46
  double dark_noise_electrons = 0;                   // ne_dark (5.11.4)
  double saturation_electrons = 0;                   // SEe- (5.11.5), +inf if disabled
  // EOIR Sensor Optics
  double focal_length_cm = 0, f_number = 0, entrance_pupil_diameter_cm = 0;
  double diffraction_wavelength_um = 0;
  double airy_disk_diameter_mrad = 0, rayleigh_resolution_mrad = 0, sparrow_resolution_mrad = 0;
  double ensquared_energy = 0;  // eq. 42
  Curve diffraction_otf, optics_otf, jitter_otf;
  Curve horizontal_detector_mtf, vertical_detector_mtf;
};

// Validates `p` (universe::validate: throws eoir::Error naming the field) and
// computes every static metric, including the PSF by FFT and the ensquared
// energy.
StaticMetrics compute_static_metrics(const SensorParameters& p);

}  // namespace eoir::sensor
