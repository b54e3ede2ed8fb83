// Optical transfer functions (spec 5.6, eqs. 33-39).
//
// Frequencies: image space xi' in cycles/cm in the focal plane; object space
// xi in cycles/mrad, xi = xi' f / 1000 (f in cm). The diffraction cutoff is
// 1 / (lambda F#) in image space, i.e. D / lambda cycles/rad in object space.
#pragma once

#include "universe/sensor_parameters.hpp"

namespace eoir::sensor {

using universe::SensorParameters;

// Eq. 34 against the normalised frequency nu = xi / xi_cutoff (0 for nu >= 1).
double diffraction_otf(double normalized_frequency);

// Eq. 35 (ERRATA): OQF = exp{-(2 pi Wrms)^2 [1 - exp(-2 n^2 nu^2)]}, n = 3.
constexpr double hufnagel_bumps = 3.0;
double hufnagel_oqf(double normalized_frequency, double wavefront_error_rms_waves);

// 2 J1(x) / x with its limit 1 at x -> 0 (eqs. 36-37).
double jinc(double x);

// Peak-to-peak wavefront error of longitudinal defocus delta, in waves of
// lambda_diff: W_pp = delta / (8 F#^2 lambda_diff).
double defocus_wavefront_error_pp_waves(double defocus_cm, double f_number, double wavelength_cm);
// Eq. 36 holds up to this W_pp; above it eq. 37 is used (spec 5.6.1.3).
constexpr double defocus_regime_switch_waves = 2.2;

// Eq. 36: OTF_defocus = 2 J1(x)/x, x = pi delta xi (xi_c - xi) / (F# xi_c);
// xi, xi_c in cycles/cm, delta in cm. 0 beyond the cutoff.
double defocus_otf_small(double frequency_cycles_per_cm, double cutoff_cycles_per_cm, double defocus_cm,
                         double f_number);

// Eq. 37: the product OTF_diff OTF_defocus = 2 J1(x)/x, x = pi delta xi / F#.
// Our choice: 0 beyond the diffraction cutoff (no incoherent OTF of a
// circular pupil extends past it; eq. 37 itself would not vanish there).
double defocus_diffraction_product_large(double frequency_cycles_per_cm, double cutoff_cycles_per_cm,
                                         double defocus_cm, double f_number);

// Eq. 38: exp(-2 (pi sigma xi)^2), sigma in mrad, xi in cycles/mrad.
double jitter_otf(double frequency_cycles_per_mrad, double jitter_mrad);

// The Wrms a sensor uses: the preset's value when image_quality names a
// preset, wavefront_error_rms_waves when it is custom.
double resolved_wavefront_error_rms_waves(const SensorParameters& p);

// The optics of one sensor with the OTFs of eqs. 33-39 as functions of the
// radial frequency.
struct OpticsModel {
  double focal_length_cm = 0;
  double f_number = 0;
  double diffraction_wavelength_cm = 0;
  double defocus_cm = 0;
  double wavefront_error_rms_waves = 0;
  double jitter_mrad = 0;

  static OpticsModel from_parameters(const SensorParameters& p);

  double cutoff_cycles_per_cm() const { return 1.0 / (diffraction_wavelength_cm * f_number); }
  double cutoff_cycles_per_mrad() const { return to_object(cutoff_cycles_per_cm()); }
  double to_object(double frequency_cycles_per_cm) const { return frequency_cycles_per_cm * focal_length_cm / 1000.0; }
  double to_image(double frequency_cycles_per_mrad) const {
    return frequency_cycles_per_mrad * 1000.0 / focal_length_cm;
  }
  double defocus_pp_waves() const {
    return defocus_wavefront_error_pp_waves(defocus_cm, f_number, diffraction_wavelength_cm);
  }
  // W_pp > 2.2 waves: eq. 37 replaces OTF_diff OTF_defocus.
  bool large_defocus() const { return defocus_pp_waves() > defocus_regime_switch_waves; }

  // All of these take the image-space radial frequency in cycles/cm.
  double diffraction(double frequency_cycles_per_cm) const;  // eq. 34
  double optics(double frequency_cycles_per_cm) const;       // eq. 33 (with 36 or 37)
  double jitter(double frequency_cycles_per_cm) const;       // eq. 38
  double system(double frequency_cycles_per_cm) const;       // eq. 39
};

}  // namespace eoir::sensor
