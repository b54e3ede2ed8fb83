#include "sensor/static_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "sensor/detector_mtf.hpp"
#include "sensor/otf.hpp"
#include "sensor/reference_pairs.hpp"
#include "sensor/responsivity.hpp"
#include "sensor/spatial_grid.hpp"
#include "sensor/system_psf.hpp"

namespace eoir::sensor {
namespace {

bool valid_pairs(const std::vector<ReferencePair>& pairs) {
  try {
    validate_reference_pairs(pairs, "saturation_pairs");
    return true;
  } catch (const Error&) {
    return false;
  }
}

// A report curve against object-space frequency in cycles/mrad.
template <class F>
Curve make_curve(const std::vector<double>& frequency_cycles_per_mrad, F&& f) {
  Curve c;
  c.frequency_cycles_per_mrad = frequency_cycles_per_mrad;
  c.value.reserve(frequency_cycles_per_mrad.size());
  for (double xi : frequency_cycles_per_mrad) c.value.push_back(f(xi));
  return c;
}

}  // namespace

StaticMetrics compute_static_metrics(const SensorParameters& p) {
  universe::validate(p);
  const OpticsModel optics = OpticsModel::from_parameters(p);  // resolves the image-quality preset
  StaticMetrics m;

  // Spatial (eqs. 21-24; Table 1).
  const double fov_h_rad = p.horizontal_fov_deg * constants::rad_per_deg;
  const double fov_v_rad = p.vertical_fov_deg * constants::rad_per_deg;
  m.pixel_pitch_x_cm = pixel_pitch_from_fov_cm(fov_h_rad, p.horizontal_pixels, p.focal_length_cm);
  m.pixel_pitch_y_cm = pixel_pitch_from_fov_cm(fov_v_rad, p.vertical_pixels, p.focal_length_cm);
  m.horizontal_pixels = p.horizontal_pixels;
  m.vertical_pixels = p.vertical_pixels;
  m.horizontal_fov_deg = p.horizontal_fov_deg;
  m.vertical_fov_deg = p.vertical_fov_deg;
  m.fov_solid_angle_sr = fov_h_rad * fov_v_rad;  // Omega_FOV = FOV_H FOV_V (Table 1)
  const double ifov_h_rad = ifov_rad(m.pixel_pitch_x_cm, p.focal_length_cm);
  const double ifov_v_rad = ifov_rad(m.pixel_pitch_y_cm, p.focal_length_cm);
  m.horizontal_ifov_mrad = ifov_h_rad * 1000.0;
  m.vertical_ifov_mrad = ifov_v_rad * 1000.0;
  m.ifov_solid_angle_sr = ifov_h_rad * ifov_v_rad;

  // Ensquared energy (eq. 42) and the effective quantities of Table 1.
  m.ensquared_energy = ensquared_energy(optics, m.pixel_pitch_x_cm, m.pixel_pitch_y_cm, PsfNumerics(p.fidelity));
  const double root_ensq = std::sqrt(m.ensquared_energy);
  m.effective_horizontal_fov_deg = p.horizontal_fov_deg / root_ensq;
  m.effective_vertical_fov_deg = p.vertical_fov_deg / root_ensq;
  m.effective_fov_solid_angle_sr = m.fov_solid_angle_sr / m.ensquared_energy;
  m.effective_horizontal_ifov_mrad = m.horizontal_ifov_mrad / root_ensq;
  m.effective_vertical_ifov_mrad = m.vertical_ifov_mrad / root_ensq;
  m.effective_ifov_solid_angle_sr = m.ifov_solid_angle_sr / m.ensquared_energy;

  // Spectral (spec 5.3).
  m.band_low_um = p.band_low_um;
  m.band_high_um = p.band_high_um;
  m.spectral_intervals = p.spectral_intervals;

  // Radiometric (eqs. 31-32, 43-46, spec 5.11.4-5.11.5).
  m.integration_time_ms = p.integration_time_ms;
  m.peak_radiance_responsivity = peak_radiance_responsivity(m.pixel_pitch_x_cm, m.pixel_pitch_y_cm, p.f_number,
                                                            p.band_low_um, p.integration_time_ms);
  m.peak_irradiance_responsivity =
      peak_irradiance_responsivity(m.peak_radiance_responsivity, m.ensquared_energy, ifov_h_rad, ifov_v_rad);
  const double r_l = m.peak_radiance_responsivity, r_e = m.peak_irradiance_responsivity;
  // An operating value given as irradiance or radiance, as both (the same
  // electrons: E R_peak,E = L R_peak,L).
  const auto both = [&](ApertureQuantity q, double value, double& irradiance, double& radiance) {
    irradiance = q == ApertureQuantity::irradiance ? value : irradiance_from_radiance(value, r_l, r_e);
    radiance = q == ApertureQuantity::radiance ? value : radiance_from_irradiance(value, r_l, r_e);
  };
  both(p.sensitivity_quantity, operating_sensitivity(p.sensitivity_pairs, p.integration_time_ms), m.dark_nei_W_cm2,
       m.dark_ner_W_cm2_sr);
  m.dark_noise_electrons = m.dark_nei_W_cm2 * r_e;  // = NER R_peak,L
  const double infinity = std::numeric_limits<double>::infinity();
  // With saturation off the pairs are still reported when they are valid.
  if (p.saturation_enabled || valid_pairs(p.saturation_pairs)) {
    both(p.saturation_quantity, operating_saturation(p.saturation_pairs, p.integration_time_ms), m.sei_W_cm2,
         m.ser_W_cm2_sr);
  } else {
    m.sei_W_cm2 = m.ser_W_cm2_sr = infinity;
  }
  m.saturation_electrons = p.saturation_enabled ? m.sei_W_cm2 * r_e : infinity;

  // Optics (Table 1): D = f / F#, resolutions in mrad.
  m.focal_length_cm = p.focal_length_cm;
  m.f_number = p.f_number;
  m.entrance_pupil_diameter_cm = p.focal_length_cm / p.f_number;
  m.diffraction_wavelength_um = p.diffraction_wavelength_um;
  const double lambda_over_d_mrad = optics.diffraction_wavelength_cm / m.entrance_pupil_diameter_cm * 1000.0;
  m.airy_disk_diameter_mrad = 2.44 * lambda_over_d_mrad;
  m.rayleigh_resolution_mrad = 1.22 * lambda_over_d_mrad;
  m.sparrow_resolution_mrad = lambda_over_d_mrad;

  // Report curves: otf_curve_points samples on [0, max(optics cutoff, 2 / IFOV)]
  // cycles/mrad, so that the optics curves reach their cutoff and the detector
  // footprint MTFs show their first two zeros (at ~1/IFOV and ~2/IFOV).
  const double min_ifov_mrad = std::min(m.horizontal_ifov_mrad, m.vertical_ifov_mrad);
  const double max_frequency = std::max(optics.cutoff_cycles_per_mrad(), 2.0 / min_ifov_mrad);
  std::vector<double> xi(static_cast<std::size_t>(p.fidelity.otf_curve_points));
  for (std::size_t i = 0; i < xi.size(); ++i)
    xi[i] = max_frequency * static_cast<double>(i) / static_cast<double>(xi.size() - 1);
  m.diffraction_otf = make_curve(xi, [&](double f) { return optics.diffraction(optics.to_image(f)); });
  m.optics_otf = make_curve(xi, [&](double f) { return optics.optics(optics.to_image(f)); });
  m.jitter_otf = make_curve(xi, [&](double f) { return jitter_otf(f, p.jitter_mrad); });
  m.horizontal_detector_mtf = make_curve(
      xi, [&](double f) { return detector_footprint_mtf_object(f, m.pixel_pitch_x_cm, p.focal_length_cm); });
  m.vertical_detector_mtf = make_curve(
      xi, [&](double f) { return detector_footprint_mtf_object(f, m.pixel_pitch_y_cm, p.focal_length_cm); });
  return m;
}

}  // namespace eoir::sensor
