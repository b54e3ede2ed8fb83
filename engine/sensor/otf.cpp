#include "sensor/otf.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::sensor {

double diffraction_otf(double normalized_frequency) {
  const double nu = std::abs(normalized_frequency);
  if (nu >= 1.0) return 0.0;
  return 2.0 / constants::pi * (std::acos(nu) - nu * std::sqrt(1.0 - nu * nu));
}

double hufnagel_oqf(double normalized_frequency, double wavefront_error_rms_waves) {
  const double w = 2.0 * constants::pi * wavefront_error_rms_waves;
  const double nu = normalized_frequency;
  return std::exp(-w * w * (1.0 - std::exp(-2.0 * hufnagel_bumps * hufnagel_bumps * nu * nu)));
}

double jinc(double x) {
  // 2 J1(x)/x = 1 - x^2/8 + x^4/192 - ...; the series is exact to 1e-16 below 1e-4.
  if (std::abs(x) < 1.0e-4) return 1.0 - x * x / 8.0;
  return 2.0 * std::cyl_bessel_j(1.0, std::abs(x)) / std::abs(x);
}

double defocus_wavefront_error_pp_waves(double defocus_cm, double f_number, double wavelength_cm) {
  return std::abs(defocus_cm) / (8.0 * f_number * f_number * wavelength_cm);
}

double defocus_otf_small(double frequency_cycles_per_cm, double cutoff_cycles_per_cm, double defocus_cm,
                         double f_number) {
  const double xi = std::abs(frequency_cycles_per_cm);
  if (xi >= cutoff_cycles_per_cm) return 0.0;
  const double x = constants::pi * defocus_cm * xi * (cutoff_cycles_per_cm - xi) / (f_number * cutoff_cycles_per_cm);
  return jinc(x);
}

double defocus_diffraction_product_large(double frequency_cycles_per_cm, double cutoff_cycles_per_cm,
                                         double defocus_cm, double f_number) {
  const double xi = std::abs(frequency_cycles_per_cm);
  if (xi >= cutoff_cycles_per_cm) return 0.0;
  return jinc(constants::pi * defocus_cm * xi / f_number);
}

double jitter_otf(double frequency_cycles_per_mrad, double jitter_mrad) {
  const double a = constants::pi * jitter_mrad * frequency_cycles_per_mrad;
  return std::exp(-2.0 * a * a);
}

double resolved_wavefront_error_rms_waves(const SensorParameters& p) {
  if (p.image_quality == universe::ImageQuality::custom) return p.wavefront_error_rms_waves;
  return universe::image_quality_presets()[static_cast<std::size_t>(p.image_quality)].wavefront_error_rms_waves;
}

OpticsModel OpticsModel::from_parameters(const SensorParameters& p) {
  OpticsModel m;
  m.focal_length_cm = p.focal_length_cm;
  m.f_number = p.f_number;
  m.diffraction_wavelength_cm = p.diffraction_wavelength_um * constants::cm_per_um;
  m.defocus_cm = p.defocus_mm * constants::cm_per_mm;
  m.wavefront_error_rms_waves = resolved_wavefront_error_rms_waves(p);
  m.jitter_mrad = p.jitter_mrad;
  return m;
}

double OpticsModel::diffraction(double frequency_cycles_per_cm) const {
  return diffraction_otf(frequency_cycles_per_cm / cutoff_cycles_per_cm());
}

double OpticsModel::optics(double frequency_cycles_per_cm) const {
  const double cutoff = cutoff_cycles_per_cm();
  const double nu = std::abs(frequency_cycles_per_cm) / cutoff;
  if (nu >= 1.0) return 0.0;
  const double oqf = wavefront_error_rms_waves > 0.0 ? hufnagel_oqf(nu, wavefront_error_rms_waves) : 1.0;
  if (defocus_cm == 0.0) return diffraction_otf(nu) * oqf;
  if (large_defocus())
    return defocus_diffraction_product_large(frequency_cycles_per_cm, cutoff, defocus_cm, f_number) * oqf;
  return diffraction_otf(nu) * oqf * defocus_otf_small(frequency_cycles_per_cm, cutoff, defocus_cm, f_number);
}

double OpticsModel::jitter(double frequency_cycles_per_cm) const {
  if (jitter_mrad == 0.0) return 1.0;
  return jitter_otf(to_object(frequency_cycles_per_cm), jitter_mrad);
}

double OpticsModel::system(double frequency_cycles_per_cm) const {
  return optics(frequency_cycles_per_cm) * jitter(frequency_cycles_per_cm);
}

}  // namespace eoir::sensor
