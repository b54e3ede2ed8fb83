#include "atmosphere/rayleigh.hpp"

#include <cmath>

#include "atmosphere/profile.hpp"

namespace eoir::atmosphere {

double rayleigh_sea_level_optical_depth(double wavelength_um) {
  const double l2 = wavelength_um * wavelength_um;
  if (wavelength_um > 4.0) return rayleigh_sea_level_optical_depth(4.0) * std::pow(4.0 / wavelength_um, 4.0);
  return 0.0021520 * (1.0455996 - 341.29061 / l2 - 0.90230850 * l2) / (1.0 + 0.0027059889 / l2 - 85.968563 * l2);
}

double rayleigh_reference_column_m2() {
  // Eq. 11 at 45 deg (cos 2 phi = 0): g0 = 980.6160 cm s^-2; eq. 12 at the
  // column's mass-weighted altitude z_c = 0.73737 z + 5517.56 m for z = 0
  // (g in cm s^-2, z in m).
  const double zc = 5517.56;
  const double g = (980.6160 - 3.085462e-4 * zc + 7.254e-11 * zc * zc - 1.517e-17 * zc * zc * zc) * 1e-2;
  const double m_air_kg = 28.9595e-3 / kAvogadro_per_mol;  // 360 ppm CO2 (their eq. 17)
  return 101325.0 / (m_air_kg * g);
}

double rayleigh_cross_section_m2(double wavelength_um) {
  return rayleigh_sea_level_optical_depth(wavelength_um) / rayleigh_reference_column_m2();
}

double rayleigh_phase(double cos_scattering) {
  constexpr double rho = 0.0279, gamma = rho / (2.0 - rho);
  return 3.0 / (4.0 * (1.0 + 2.0 * gamma)) * ((1.0 + 3.0 * gamma) + (1.0 - gamma) * cos_scattering * cos_scattering);
}

}  // namespace eoir::atmosphere
