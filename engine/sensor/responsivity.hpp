// Radiance and irradiance responsivity (spec 5.4-5.5).
#pragma once

namespace eoir::sensor {

// h c in J cm, for eq. 31 with the wavelength in cm.
double planck_times_c_J_cm();

// Peak radiance responsivity, eq. 31 (eq. 26 with the assumption of eq. 30,
// tau_opt eta = 0.8 lambda_low / lambda):
//   R_peak,L = pi A_d 0.8 lambda_low t_i / ((4 F#^2 + 1) h c)
// with A_d = p_x p_y in cm^2, lambda_low in cm, t_i in s, h c in J cm.
// Returns electrons / (W / (cm^2 sr)).
double peak_radiance_responsivity(double pitch_x_cm, double pitch_y_cm, double f_number, double band_low_um,
                                  double integration_time_ms);

// Spectral radiance responsivity R_L(lambda), eq. 31: constant (= peak) inside
// the band [low, high] and zero outside (the boxcar RSR of eqs. 28-30).
double radiance_responsivity(double wavelength_um, double band_low_um, double band_high_um, double peak_radiance);

// Peak irradiance responsivity, eq. 32:
//   R_peak,E = R_peak,L ENSQ / (IFOV_H IFOV_V), IFOVs in rad.
// Returns electrons / (W / cm^2).
double peak_irradiance_responsivity(double peak_radiance, double ensquared_energy, double ifov_h_rad,
                                    double ifov_v_rad);

}  // namespace eoir::sensor
