// Physical constants (CODATA 2018 exact SI values) and unit conversions.
#pragma once

namespace eoir::constants {
constexpr double pi = 3.14159265358979323846;
constexpr double ln10 = 2.30258509299404568402;  // ln 10
constexpr double planck_J_s = 6.62607015e-34;
constexpr double speed_of_light_m_per_s = 299792458.0;
constexpr double speed_of_light_cm_per_s = 2.99792458e10;
constexpr double boltzmann_J_per_K = 1.380649e-23;
constexpr double deg_per_rad = 180.0 / pi;
constexpr double rad_per_deg = pi / 180.0;
constexpr double cm_per_um = 1.0e-4;
constexpr double cm_per_mm = 0.1;
constexpr double seconds_per_day = 86400.0;
constexpr double au_m = 149597870700.0;
}  // namespace eoir::constants
