// Independent references for the spec 6 validation tests (tests/validation/):
// everything here is computed from first principles or from the published
// data files, never through the engine's own code paths.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scenario_host.hpp"

namespace eoir::validation {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
constexpr double kAu_m = 149597870700.0;        // IAU 2012 resolution B2
constexpr double kWgs84A_m = 6378137.0;

// A 3-vector of this namespace (so that its operators are found by ADL).
struct V3 {
  double v[3];
  double& operator[](std::size_t i) { return v[i]; }
  double operator[](std::size_t i) const { return v[i]; }
};
inline V3 operator+(const V3& a, const V3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline V3 operator-(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline V3 operator*(double s, const V3& a) { return {s * a[0], s * a[1], s * a[2]}; }
double dot(const V3& a, const V3& b);
double norm(const V3& a);
V3 unit(const V3& a);
V3 cross(const V3& a, const V3& b);

// Planck's law (spec eq. 5) with the 2018 CODATA constants, W cm^-2 sr^-1 um^-1.
double planck(double wavelength_um, double temperature_K);
// Its band integral by composite Simpson with `n` (even) intervals, W cm^-2 sr^-1.
double planck_band(double low_um, double high_um, double temperature_K, int n = 4000);

// The ASTM E-490-00a table as published (pyspectral/data/e490_00a.dat,
// wavelength um, W m^-2 um^-1), read here from the Debian package's file,
// not from the engine's converted copy.
struct Table {
  std::vector<double> x, y;
};
Table read_e490(const std::string& path);
// Integral of the table's piecewise-linear interpolant over [a, b] (0 outside
// the table), in the table's units times um.
double integrate_linear(const Table& t, double a, double b);

// Geocentric position of the Sun (m, ICRS/J2000 axes) from ERFA's eraEpv00
// (VSOP2000-based, a few km), at a UTC ISO time.
V3 sun_geocentric_m(const std::string& iso_utc, double seconds_after = 0.0);
// TT two-part Julian date of an ISO UTC time plus seconds (via ERFA).
void tt_jd(const std::string& iso_utc, double seconds_after, double& jd1, double& jd2);

// A point at geodetic latitude 0 (on the WGS84 equator, a circle of radius
// a), longitude lon_deg, altitude alt_m, Earth-fixed: ((a + h) cos lon,
// (a + h) sin lon, 0). Its inverse for a point in that plane.
V3 equator_point(double lon_deg, double alt_m);
void equator_geodetic(double x_m, double y_m, double& lon_deg, double& alt_m);

// Scenario edits.
void set_fixed_geodetic(nlohmann::json& object, double lat_deg, double lon_deg, double alt_m);
void set_fixed_j2000(nlohmann::json& object, const std::string& start_iso, const std::string& stop_iso,
                     const V3& position_m);
nlohmann::json& object_named(nlohmann::json& doc, const std::string& name);

// The pick of one scene sample with its spectral radiance vector.
struct SpectralPick {
  test::Pick pick;
  double temperature_K = 0;
  std::vector<double> wavelengths_um, radiance;  // W cm^-2 sr^-1 um^-1
};
SpectralPick spectral_pick(test::ScenarioHost& host, int x, int y, const std::string& sensor = "Sensor1");
// eoir_target_spectrum_get: the target's spectral irradiance at the aperture.
void target_spectrum(test::ScenarioHost& host, const std::string& target, std::vector<double>& wavelengths_um,
                     std::vector<double>& irradiance_W_cm2_um, const std::string& sensor = "Sensor1");

}  // namespace eoir::validation
