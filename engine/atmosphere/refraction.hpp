// Astronomical refraction near the ground (spec 4.3.1.1; issue 20 item 6):
// how much higher a source appears than it is. Saemundsson (1986, Sky and
// Telescope 72, 70): R = 1.02' / tan(h + 10.3 / (h + 5.11)) from the true
// altitude h in degrees, scaled by (P / 1010 hPa)(283 K / T), valid to the
// horizon (within 0.1' of Bennett's inverse).
#pragma once

namespace eoir::atmosphere {

// Refraction (rad, >= 0) of a source at true elevation `true_elevation_rad`
// seen through air at the observer's pressure and temperature.
double refraction_from_true_rad(double true_elevation_rad, double pressure_Pa, double temperature_K);

}  // namespace eoir::atmosphere
