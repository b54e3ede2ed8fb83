// Test oracle: apparent V magnitudes of the planets from Mallama & Hilton
// (2018), "Computing apparent planetary magnitudes for The Astronomical
// Almanac", Astronomy and Computing 25, 10-24 (arXiv:1808.01973), eqs. 2
// (Mercury), 3-4 (Venus), 6-7 (Mars, without the rotational and orbital
// corrections L(lambda_e), L(Ls) of up to ~0.06 mag), 8-9 (Jupiter), 11-12
// (Saturn's globe), 13-14 (Uranus, sub-latitude term left out) and 16-17
// (Neptune after 2000.0), transcribed from the paper for the tests (the
// engine's own transcription is engine/radiometry/disk_photometry.cpp).
// r: Sun-planet distance [au]; delta: observer-planet distance [au];
// alpha: phase angle Sun-planet-observer [deg]. Branch limits as in the
// paper's reference code (Ap_Mag_V3.f90).
#pragma once
#include <cmath>

namespace eoir::test_oracle {

inline double venus_v_mag(double r_au, double delta_au, double alpha_deg) {
  const double a = alpha_deg;
  const double distance = 5.0 * std::log10(r_au * delta_au);
  if (a < 163.7)  // eq. 3
    return -4.384 + distance - 1.044e-3 * a + 3.687e-4 * a * a - 2.814e-6 * a * a * a + 8.938e-9 * a * a * a * a;
  return 236.05828 + distance - 2.81914 * a + 8.39034e-3 * a * a;  // eq. 4
}

inline double mars_v_mag(double r_au, double delta_au, double alpha_deg) {
  const double a = alpha_deg;
  const double distance = 5.0 * std::log10(r_au * delta_au);
  if (a <= 50.0) return -1.601 + distance + 2.267e-2 * a - 1.302e-4 * a * a;  // eq. 6
  return -0.367 + distance - 0.02573 * a + 0.0003445 * a * a;                  // eq. 7
}

inline double jupiter_v_mag(double r_au, double delta_au, double alpha_deg) {
  const double a = alpha_deg;
  const double distance = 5.0 * std::log10(r_au * delta_au);
  if (a <= 12.0) return -9.395 + distance - 3.7e-4 * a + 6.16e-4 * a * a;  // eq. 8
  const double x = a / 180.0;                                              // eq. 9
  return -9.428 + distance -
         2.5 * std::log10(1.0 - 1.507 * x - 0.363 * x * x - 0.062 * x * x * x + 2.809 * x * x * x * x -
                          1.876 * x * x * x * x * x);
}

inline double mercury_v_mag(double r_au, double delta_au, double a) {
  const double distance = 5.0 * std::log10(r_au * delta_au);
  return -0.613 + distance + 6.3280e-02 * a - 1.6336e-03 * std::pow(a, 2) + 3.3644e-05 * std::pow(a, 3) -
         3.4265e-07 * std::pow(a, 4) + 1.6893e-09 * std::pow(a, 5) - 3.0334e-12 * std::pow(a, 6);  // eq. 2
}

inline double saturn_globe_v_mag(double r_au, double delta_au, double a) {
  const double distance = 5.0 * std::log10(r_au * delta_au);
  if (a <= 6.5) return -8.95 + distance - 3.7e-4 * a + 6.16e-4 * a * a;  // eq. 11
  return -8.94 + distance + 2.446e-4 * a + 2.672e-4 * a * a - 1.506e-6 * std::pow(a, 3) +
         4.767e-9 * std::pow(a, 4);  // eq. 12
}

inline double uranus_v_mag(double r_au, double delta_au, double a) {
  const double distance = 5.0 * std::log10(r_au * delta_au);
  if (a <= 3.1) return -7.110 + distance;                // eq. 13 (sub-latitude 0)
  return -7.110 + distance + 6.587e-3 * a + 1.045e-4 * a * a;  // eq. 14
}

inline double neptune_v_mag(double r_au, double delta_au, double a) {
  const double distance = 5.0 * std::log10(r_au * delta_au);
  if (a <= 1.9) return -7.00 + distance;                  // eq. 16 (after 2000.0)
  return -7.00 + distance + 7.944e-3 * a + 9.617e-5 * a * a;  // eq. 17
}

}  // namespace eoir::test_oracle
