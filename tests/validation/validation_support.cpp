#include "validation_support.hpp"

#include <erfa.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace eoir::validation {

double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const V3& a) { return std::sqrt(dot(a, a)); }
V3 unit(const V3& a) { return (1.0 / norm(a)) * a; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double planck(double wavelength_um, double T) {
  if (T <= 0) return 0.0;
  constexpr double h = 6.62607015e-34, c = 299792458.0, k = 1.380649e-23;
  const double l = wavelength_um * 1e-6;  // m
  // W m^-2 sr^-1 m^-1 -> W cm^-2 sr^-1 um^-1: 1e-4 * 1e-6.
  return 2.0 * h * c * c / std::pow(l, 5) / std::expm1(h * c / (l * k * T)) * 1e-10;
}

double planck_band(double a, double b, double T, int n) {
  if (T <= 0) return 0.0;
  const double h = (b - a) / n;
  double s = planck(a, T) + planck(b, T);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * planck(a + i * h, T);
  return s * h / 3.0;
}

Table read_e490(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  Table t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    double x = 0, y = 0;
    if (!(s >> x >> y)) throw std::runtime_error(path + ": bad line '" + line + "'");
    t.x.push_back(x);
    t.y.push_back(y);
  }
  return t;
}

double integrate_linear(const Table& t, double a, double b) {
  double s = 0;
  for (std::size_t i = 0; i + 1 < t.x.size(); ++i) {
    const double x0 = t.x[i], x1 = t.x[i + 1];
    const double lo = std::max(a, x0), hi = std::min(b, x1);
    if (!(hi > lo)) continue;
    const auto f = [&](double x) { return t.y[i] + (t.y[i + 1] - t.y[i]) * (x - x0) / (x1 - x0); };
    s += 0.5 * (f(lo) + f(hi)) * (hi - lo);
  }
  return s;
}

void tt_jd(const std::string& iso, double seconds_after, double& jd1, double& jd2) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0;
  double sec = 0;
  if (std::sscanf(iso.c_str(), "%d-%d-%dT%d:%d:%lfZ", &y, &mo, &d, &h, &mi, &sec) != 6)
    throw std::runtime_error("bad ISO time " + iso);
  double u1 = 0, u2 = 0, a1 = 0, a2 = 0;
  if (eraDtf2d("UTC", y, mo, d, h, mi, sec, &u1, &u2) < 0) throw std::runtime_error("eraDtf2d " + iso);
  u2 += seconds_after / 86400.0;
  if (eraUtctai(u1, u2, &a1, &a2) < 0 || eraTaitt(a1, a2, &jd1, &jd2) != 0)
    throw std::runtime_error("UTC to TT " + iso);
}

V3 sun_geocentric_m(const std::string& iso, double seconds_after) {
  double t1 = 0, t2 = 0;
  tt_jd(iso, seconds_after, t1, t2);
  double pvh[2][3], pvb[2][3];
  eraEpv00(t1, t2, pvh, pvb);  // heliocentric Earth, au (BCRS axes)
  return {-pvh[0][0] * kAu_m, -pvh[0][1] * kAu_m, -pvh[0][2] * kAu_m};
}

V3 equator_point(double lon_deg, double alt_m) {
  const double r = kWgs84A_m + alt_m;
  return {r * std::cos(lon_deg * kDeg), r * std::sin(lon_deg * kDeg), 0.0};
}

void equator_geodetic(double x, double y, double& lon_deg, double& alt_m) {
  lon_deg = std::atan2(y, x) / kDeg;
  alt_m = std::hypot(x, y) - kWgs84A_m;
}

void set_fixed_geodetic(nlohmann::json& o, double lat, double lon, double alt) {
  o["motion"] = {{"type", "fixed_geodetic"}, {"lat_deg", lat}, {"lon_deg", lon}, {"alt_m", alt}};
}

void set_fixed_j2000(nlohmann::json& o, const std::string& start, const std::string& stop, const V3& p) {
  nlohmann::json pos = {p[0], p[1], p[2]}, zero = {0.0, 0.0, 0.0};
  o["motion"] = {{"type", "ephemeris"},
                 {"frame", "j2000"},
                 {"points",
                  {{{"time", start}, {"position_m", pos}, {"velocity_m_s", zero}},
                   {{"time", stop}, {"position_m", pos}, {"velocity_m_s", zero}}}}};
}

nlohmann::json& object_named(nlohmann::json& doc, const std::string& name) {
  for (auto& o : doc["objects"])
    if (o["name"] == name) return o;
  throw std::runtime_error("no object " + name + " in the scenario");
}

namespace {
void check(const eoir_api_v1& api, eoir_status st, const std::string& what) {
  if (st != EOIR_OK) throw std::runtime_error(what + ": " + api.last_error());
}
}  // namespace

SpectralPick spectral_pick(test::ScenarioHost& host, int x, int y, const std::string& sensor) {
  const eoir_api_v1& api = host.api();
  eoir_pick p{};
  p.struct_size = sizeof p;
  size_t count = 0;
  check(api, api.pick_get(host.handle(), sensor.c_str(), 0, static_cast<uint32_t>(x), static_cast<uint32_t>(y), &p,
                          nullptr, nullptr, 0, &count),
        "pick");
  SpectralPick out;
  out.wavelengths_um.resize(count);
  out.radiance.resize(count);
  check(api, api.pick_get(host.handle(), sensor.c_str(), 0, static_cast<uint32_t>(x), static_cast<uint32_t>(y), &p,
                          out.wavelengths_um.data(), out.radiance.data(), count, &count),
        "pick");
  out.pick = test::Pick{p.hit != 0, p.object, p.range_m, p.effective_radiance, p.latitude_deg, p.longitude_deg};
  out.temperature_K = p.temperature_K;
  return out;
}

void target_spectrum(test::ScenarioHost& host, const std::string& target, std::vector<double>& wl,
                     std::vector<double>& E, const std::string& sensor) {
  const eoir_api_v1& api = host.api();
  size_t count = 0;
  check(api, api.target_spectrum_get(host.handle(), sensor.c_str(), target.c_str(), nullptr, nullptr, 0, &count),
        "target spectrum");
  wl.resize(count);
  E.resize(count);
  check(api, api.target_spectrum_get(host.handle(), sensor.c_str(), target.c_str(), wl.data(), E.data(), count, &count),
        "target spectrum");
}

}  // namespace eoir::validation
