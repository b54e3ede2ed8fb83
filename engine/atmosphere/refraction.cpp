#include "atmosphere/refraction.hpp"

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"

namespace eoir::atmosphere {

double refraction_from_true_rad(double true_elevation_rad, double pressure_Pa, double temperature_K) {
  if (!(pressure_Pa > 0) || !(temperature_K > 0)) return 0.0;
  // Below -1 deg the formula's pole (h = -5.11 - ...) nears: held at its -1 deg value.
  const double h = std::max(true_elevation_rad * constants::deg_per_rad, -1.0);
  const double arcmin = 1.02 / std::tan((h + 10.3 / (h + 5.11)) * constants::rad_per_deg);
  const double scale = (pressure_Pa / 101000.0) * (283.0 / temperature_K);
  return std::max(0.0, arcmin * scale / 60.0 * constants::rad_per_deg);
}

}  // namespace eoir::atmosphere
