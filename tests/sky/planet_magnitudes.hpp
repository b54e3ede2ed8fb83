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
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "../support/csv_rows.hpp"

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

// Mars' corrections L(lambda_e) + L(Ls) of eqs. 6-7 (Mallama 2007 Tables 6
// and 8), for the tests: the table of data/planets/
// mars_brightness_corrections.csv read here (36 rows, 0-350 deg), the cubic
// through the four nodes around the angle (the engine interpolates with
// Stirling's five-node formula: they differ by a few 0.001 mag), and Mars'
// orientation from the IAU WGCCRE 2015 elements (Archinal et al. 2018:
// pole RA 317.68143 - 0.1061 T, Dec 52.88650 - 0.0609 T, W = 176.630 +
// 350.89198226 d).
struct MarsCorrectionTables {
  std::vector<double> rotation, orbit;
};

// Allen's (1973) lunar phase law (tests/data/allen_1973_lunar_phase_law.csv):
// (phase angle deg, magnitude below full) rows.
inline std::vector<std::pair<double, double>> allen_lunar_phase_table(const std::string& path) {
  std::vector<std::pair<double, double>> rows;
  for (const std::vector<std::string>& cells : eoir_test::csv_rows(path))
    rows.emplace_back(std::stod(cells.at(0)), std::stod(cells.at(1)));
  return rows;
}

inline MarsCorrectionTables read_mars_corrections(const std::string& path) {
  MarsCorrectionTables t;
  for (const std::vector<std::string>& cells : eoir_test::csv_rows(path)) {
    if (cells.size() < 3) throw std::runtime_error(path + ": 3 columns expected");
    t.rotation.push_back(std::stod(cells[1]));
    t.orbit.push_back(std::stod(cells[2]));
  }
  if (t.rotation.size() != 36) throw std::runtime_error(path + ": 36 rows expected");
  return t;
}

inline double cubic_on_circle(const std::vector<double>& table, double deg) {
  const double x = std::fmod(std::fmod(deg, 360.0) + 360.0, 360.0) / 10.0;
  const int k = static_cast<int>(x) % 36;
  const double u = x - std::floor(x);
  const auto f = [&](int i) { return table[static_cast<std::size_t>((k + i + 36) % 36)]; };
  return -u * (u - 1) * (u - 2) / 6 * f(-1) + (u + 1) * (u - 1) * (u - 2) / 2 * f(0) -
         (u + 1) * u * (u - 2) / 2 * f(1) + (u + 1) * u * (u - 1) / 6 * f(2);
}

// West longitude [deg] on Mars under the unit direction `dir` (J2000, from
// Mars' centre), d days (TDB) after J2000.0 at Mars (light time taken off).
inline double mars_west_longitude_deg(const double dir[3], double d) {
  const double deg = 3.14159265358979323846 / 180.0, T = d / 36525.0;
  const double ra = (317.68143 - 0.1061 * T) * deg, dec = (52.88650 - 0.0609 * T) * deg;
  const double node[3] = {-std::sin(ra), std::cos(ra), 0.0};  // the equator's ascending node on the ICRF equator
  const double east[3] = {-std::sin(dec) * std::cos(ra), -std::sin(dec) * std::sin(ra), std::cos(dec)};
  const double theta = std::atan2(dir[0] * east[0] + dir[1] * east[1] + dir[2] * east[2],
                                  dir[0] * node[0] + dir[1] * node[1] + dir[2] * node[2]) /
                       deg;
  return std::fmod(std::fmod(176.630 + 350.89198226 * d - theta, 360.0) + 360.0, 360.0);
}

// L(lambda_e) + L(Ls) [mag] from the sub-observer and sub-solar west
// longitudes and Mars' heliocentric J2000 ecliptic longitude [deg].
inline double mars_corrections_mag(const MarsCorrectionTables& t, double sub_observer_west, double sub_solar_west,
                                   double helio_ecliptic_lon) {
  double cm = 0.5 * (sub_observer_west + sub_solar_west);
  if (std::fabs(sub_observer_west - sub_solar_west) > 180.0) cm += 180.0;
  return cubic_on_circle(t.rotation, cm) + cubic_on_circle(t.orbit, helio_ecliptic_lon - 85.0);
}

// The Uranus sub-latitude term of eqs. 13-14, -0.00084 mag per degree of
// the mean absolute planetographic latitude under the Sun and the observer,
// from unit directions (J2000, from Uranus' centre): IAU WGCCRE 2015 pole
// RA 257.311, Dec -15.175; radii 25,559 and 24,973 km.
inline double uranus_sub_latitude_term_mag(const double to_sun[3], const double to_observer[3]) {
  const double deg = 3.14159265358979323846 / 180.0;
  const double ra = 257.311 * deg, dec = -15.175 * deg;
  const double pole[3] = {std::cos(dec) * std::cos(ra), std::cos(dec) * std::sin(ra), std::sin(dec)};
  const double k = (25559.0 / 24973.0) * (25559.0 / 24973.0);
  const auto graphic_deg = [&](const double u[3]) {
    const double s = pole[0] * u[0] + pole[1] * u[1] + pole[2] * u[2];
    return std::atan2(s * k, std::sqrt(std::fmax(0.0, 1.0 - s * s))) / deg;
  };
  return -0.00084 * 0.5 * (std::fabs(graphic_deg(to_sun)) + std::fabs(graphic_deg(to_observer)));
}

}  // namespace eoir::test_oracle
