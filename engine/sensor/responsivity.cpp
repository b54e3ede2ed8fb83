#include "sensor/responsivity.hpp"

#include "core/constants.hpp"

namespace eoir::sensor {

double planck_times_c_J_cm() { return constants::planck_J_s * constants::speed_of_light_cm_per_s; }

double peak_radiance_responsivity(double pitch_x_cm, double pitch_y_cm, double f_number, double band_low_um,
                                  double integration_time_ms) {
  const double detector_area_cm2 = pitch_x_cm * pitch_y_cm;  // 100 % fill factor (spec 5.1)
  const double lambda_low_cm = band_low_um * constants::cm_per_um;
  const double integration_time_s = integration_time_ms * 1.0e-3;
  return constants::pi * detector_area_cm2 * 0.8 * lambda_low_cm * integration_time_s /
         ((4.0 * f_number * f_number + 1.0) * planck_times_c_J_cm());
}

double radiance_responsivity(double wavelength_um, double band_low_um, double band_high_um, double peak_radiance) {
  return (wavelength_um >= band_low_um && wavelength_um <= band_high_um) ? peak_radiance : 0.0;
}

double peak_irradiance_responsivity(double peak_radiance, double ensquared_energy, double ifov_h_rad,
                                    double ifov_v_rad) {
  return peak_radiance * ensquared_energy / (ifov_h_rad * ifov_v_rad);
}

}  // namespace eoir::sensor
