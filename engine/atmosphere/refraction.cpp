#include "atmosphere/refraction.hpp"

#include <erfa.h>

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace eoir::atmosphere {
namespace {
constexpr double kErfaFrom_deg = 10.0, kBennettBelow_deg = 5.0;
}  // namespace

RefractionConstants refraction_constants(double pressure_Pa, double temperature_K, double relative_humidity,
                                         double wavelength_um) {
  RefractionConstants c;
  if (!(pressure_Pa > 0) || !(temperature_K > 0)) return c;
  eraRefco(pressure_Pa / 100.0, temperature_K - 273.15, std::clamp(relative_humidity, 0.0, 1.0),
           std::clamp(wavelength_um, 0.3, 100.0), &c.a_rad, &c.b_rad);
  c.bennett_scale = (pressure_Pa / 101000.0) * (283.0 / temperature_K);
  return c;
}

double refraction_from_apparent_rad(const RefractionConstants& c, double h_rad) {
  const double h_deg = h_rad * constants::deg_per_rad;
  const auto erfa = [&](double h) {
    const double t = std::tan(constants::pi / 2 - h * constants::rad_per_deg);
    return c.a_rad * t + c.b_rad * t * t * t;
  };
  const auto bennett = [&](double h) {
    const double hh = std::max(h, -1.0);  // the formula's pole lies at -2.1 deg
    return c.bennett_scale / std::tan((hh + 7.31 / (hh + 4.4)) * constants::rad_per_deg) / 60.0 * constants::rad_per_deg;
  };
  double r = 0;
  if (h_deg >= kErfaFrom_deg) {
    r = erfa(h_deg);
  } else if (h_deg <= kBennettBelow_deg) {
    r = bennett(h_deg);
  } else {
    const double f = (h_deg - kBennettBelow_deg) / (kErfaFrom_deg - kBennettBelow_deg);
    r = (1.0 - f) * bennett(h_deg) + f * erfa(h_deg);
  }
  return std::max(0.0, r);
}

double refraction_from_true_rad(const RefractionConstants& c, double e_rad) {
  // Newton on f(R) = R - R_apparent(e + R), f' = 1 - dR_apparent/dh (< 0.3).
  double r = refraction_from_apparent_rad(c, e_rad);
  constexpr double dh = 1e-7;
  for (int i = 0; i < 6; ++i) {
    const double f = r - refraction_from_apparent_rad(c, e_rad + r);
    const double slope = (refraction_from_apparent_rad(c, e_rad + r + dh) - refraction_from_apparent_rad(c, e_rad + r - dh)) / (2 * dh);
    r -= f / (1.0 - slope);
  }
  return std::max(0.0, r);
}

}  // namespace eoir::atmosphere
