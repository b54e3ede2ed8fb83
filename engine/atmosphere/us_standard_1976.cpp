#include "atmosphere/us_standard_1976.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::atmosphere {
namespace {

// Table 4: geopotential altitude of each layer's base (m'), molecular-scale
// temperature there (K) and its gradient (K/m').
struct Layer {
  double base_m, base_K, gradient_K_m;
};
constexpr Layer kLayers[] = {{0.0, 288.15, -6.5e-3},     {11000.0, 216.65, 0.0},   {20000.0, 216.65, 1.0e-3},
                             {32000.0, 228.65, 2.8e-3},  {47000.0, 270.65, 0.0},   {51000.0, 270.65, -2.8e-3},
                             {71000.0, 214.65, -2.0e-3}, {84852.0, 186.946, 0.0}};
constexpr double kGMR = us76_g0_m_s2 * us76_molar_mass_kg_mol / us76_gas_constant_J_mol_K;  // K/m'
constexpr double k86km_m = 86000.0;

// Table 8: M/M0 from 80 to 86 km every 0.5 km.
constexpr double kMolarRatio[] = {1.000000, 0.999996, 0.999988, 0.999969, 0.999938, 0.999904, 0.999864,
                                  0.999822, 0.999778, 0.999731, 0.999681, 0.999679, 0.999579};

double geopotential_m(double z_m) { return us76_earth_radius_m * z_m / (us76_earth_radius_m + z_m); }

double molar_ratio(double z_m) {
  if (z_m <= 80000.0) return 1.0;
  const double x = std::min((z_m - 80000.0) / 500.0, 12.0);
  const int i = std::min(static_cast<int>(x), 11);
  return kMolarRatio[i] + (x - i) * (kMolarRatio[i + 1] - kMolarRatio[i]);
}

// Eqs. 33a/33b below 86 km: molecular-scale temperature and pressure.
void lower(double z_m, double& tm_K, double& p_Pa) {
  const double H = geopotential_m(z_m);
  double p_base = us76_sea_level_pressure_Pa;
  for (int i = 0;; ++i) {
    const Layer& l = kLayers[i];
    const double top = kLayers[i + 1].base_m;
    const double dH = std::min(H, top) - l.base_m;
    const double t = l.base_K + l.gradient_K_m * dH;
    const double p = l.gradient_K_m == 0.0 ? p_base * std::exp(-kGMR * dH / l.base_K)
                                           : p_base * std::pow(l.base_K / t, kGMR / l.gradient_K_m);
    if (H <= top || i == 6) {
      tm_K = t;
      p_Pa = p;
      return;
    }
    p_base = p;
  }
}

// Eqs. 25-27: kinetic temperature from 86 to 110 km.
double upper_temperature_K(double z_m) {
  const double z_km = z_m / 1000.0;
  if (z_km <= 91.0) return 186.8673;
  const double Tc = 263.1905, A = -76.3232, a = -19.9429;
  const double x = (z_km - 91.0) / a;
  return Tc + A * std::sqrt(std::max(0.0, 1.0 - x * x));
}

double gravity_m_s2(double z_m) {
  const double s = us76_earth_radius_m / (us76_earth_radius_m + z_m);
  return us76_g0_m_s2 * s * s;
}
}  // namespace

StandardAtmosphereState us_standard_1976(double altitude_m) {
  const double z = std::clamp(altitude_m, 0.0, us76_top_altitude_m);
  StandardAtmosphereState s;
  if (z <= k86km_m) {
    double tm = 0, p = 0;
    lower(z, tm, p);
    s.temperature_K = tm * molar_ratio(z);
    s.pressure_Pa = p;
    s.density_kg_m3 = p * us76_molar_mass_kg_mol / (us76_gas_constant_J_mol_K * tm);
    return s;
  }
  // Above 86 km: d ln p / dz = -g M0 / (R* T), integrated by Simpson's rule
  // in 250 m steps (the temperature is smooth there).
  double tm = 0, p = 0;
  lower(k86km_m, tm, p);
  const int steps = std::max(2, 2 * static_cast<int>(std::ceil((z - k86km_m) / 500.0)));
  const double h = (z - k86km_m) / steps;
  const auto f = [](double x) { return gravity_m_s2(x) * us76_molar_mass_kg_mol / (us76_gas_constant_J_mol_K * upper_temperature_K(x)); };
  double sum = f(k86km_m) + f(z);
  for (int i = 1; i < steps; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(k86km_m + i * h);
  s.temperature_K = upper_temperature_K(z);
  s.pressure_Pa = p * std::exp(-sum * h / 3.0);
  s.density_kg_m3 = s.pressure_Pa * us76_molar_mass_kg_mol * molar_ratio(k86km_m) /
                    (us76_gas_constant_J_mol_K * s.temperature_K);
  return s;
}

}  // namespace eoir::atmosphere
