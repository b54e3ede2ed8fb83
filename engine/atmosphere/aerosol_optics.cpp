#include "atmosphere/aerosol_optics.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "atmosphere/data_table.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::atmosphere {
namespace {
constexpr std::array<double, 4> kHumidities{0.0, 70.0, 80.0, 99.0};
// The longest wavelength used: the source's 300 um row holds placeholders.
constexpr double kLastWavelength_um = 200.0;
}  // namespace

double relative_humidity_pct(double h2o_m3, double temperature_K) {
  if (!(temperature_K > 150.0)) return 0.0;  // (Buck's formula has a pole at 16 K; no liquid water there)
  const double e_Pa = h2o_m3 * constants::boltzmann_J_per_K * temperature_K;
  const double t_C = temperature_K - 273.15;
  const double es_Pa = 611.21 * std::exp((18.678 - t_C / 234.5) * (t_C / (257.14 + t_C)));
  return std::clamp(100.0 * e_Pa / es_Pa, 0.0, 100.0);
}

AerosolSpectra AerosolSpectra::load(const std::string& data_dir, const std::string& model, double rh_pct) {
  const std::string path = data_dir + "/atmosphere/aerosol_shettle_fenn_1979.csv";
  const DataTable t = read_data_table(path);
  const std::size_t rh_col = t.column("relative_humidity_pct"), wl = t.column("wavelength_um");
  const std::size_t ext = t.column("extinction_km"), abs = t.column("absorption_km"), g = t.column("asymmetry");
  // table[h][k]: humidity h, wavelength k.
  std::array<std::vector<std::array<double, 4>>, 4> table;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.key[r] != model) continue;
    const std::vector<double>& v = t.rows[r];
    const std::string where = path + ":" + std::to_string(t.line[r]);
    for (const std::size_t c : {rh_col, wl, ext, abs, g})
      if (v[c] < 0) throw Error(Status::corrupt_file, where + ": " + t.header[c] + ": negative");
    const auto h = std::find(kHumidities.begin(), kHumidities.end(), v[rh_col]);
    if (h == kHumidities.end()) throw Error(Status::corrupt_file, where + ": humidity not 0/70/80/99");
    if (v[wl] <= kLastWavelength_um)
      table[static_cast<std::size_t>(h - kHumidities.begin())].push_back({v[wl], v[ext], v[abs], v[g]});
  }
  if (table[0].empty()) throw Error(Status::unknown_name, path + ": no aerosol model '" + model + "'");
  for (const auto& humidity : table)
    if (humidity.size() != table[0].size()) throw Error(Status::corrupt_file, path + ": " + model + ": humidities differ in rows");
  // ln(coefficient) linear in ln(100 - RH) between the bracketing humidities.
  const double rh = std::clamp(rh_pct, 0.0, 99.0);
  std::size_t j = 0;
  while (j < 2 && rh > kHumidities[j + 1]) ++j;
  const double x0 = std::log(100.0 - kHumidities[j]), x1 = std::log(100.0 - kHumidities[j + 1]);
  const double f = (std::log(100.0 - rh) - x0) / (x1 - x0);
  const auto blend = [f](double a, double b) {
    if (a > 0 && b > 0) return std::exp(std::log(a) + f * (std::log(b) - std::log(a)));
    return a + f * (b - a);
  };
  AerosolSpectra s;
  for (std::size_t k = 0; k < table[0].size(); ++k) {
    const auto& a = table[j][k];
    const auto& b = table[j + 1][k];
    s.wavelength_um_.push_back(a[0]);
    s.extinction_.push_back(blend(a[1], b[1]));
    s.absorption_.push_back(std::min(blend(a[2], b[2]), s.extinction_.back()));
    s.asymmetry_.push_back(a[3] + f * (b[3] - a[3]));
  }
  // Per unit 0.55 um extinction after the blend.
  const double e550 = s.at(0.55).extinction_per_550;
  if (e550 > 0)
    for (std::size_t k = 0; k < s.extinction_.size(); ++k) {
      s.extinction_[k] /= e550;
      s.absorption_[k] /= e550;
    }
  return s;
}

AerosolOptics AerosolSpectra::at(double wavelength_um) const {
  const std::vector<double>& w = wavelength_um_;
  const double l = std::clamp(wavelength_um, w.front(), w.back());
  const std::size_t i = std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(w.begin(), w.end(), l) - w.begin()), w.size() - 1);
  const std::size_t k = i == 0 ? 0 : i - 1;
  const double f = (l - w[k]) / (w[k + 1] - w[k]);
  AerosolOptics o;
  o.extinction_per_550 = extinction_[k] + f * (extinction_[k + 1] - extinction_[k]);
  const double absorption = absorption_[k] + f * (absorption_[k + 1] - absorption_[k]);
  o.single_scatter_albedo = o.extinction_per_550 > 0 ? 1.0 - absorption / o.extinction_per_550 : 0.0;
  o.asymmetry = asymmetry_[k] + f * (asymmetry_[k + 1] - asymmetry_[k]);
  return o;
}

double henyey_greenstein_phase(double g, double cos_scattering) {
  const double d = 1.0 + g * g - 2.0 * g * cos_scattering;
  return (1.0 - g * g) / (d * std::sqrt(d));
}

}  // namespace eoir::atmosphere
