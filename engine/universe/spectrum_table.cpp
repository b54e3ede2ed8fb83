#include "universe/spectrum_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/read_file.hpp"
#include "core/value.hpp"

namespace eoir::universe {

double sun_projected_solid_angle_sr(double distance_m) {
  const double s = std::min(1.0, sun_radius_m / distance_m);
  return constants::pi * s * s;
}

SpectrumTable SpectrumTable::load(const std::string& data_dir) {
  const std::string path = data_dir + "/solar/e490.txt";
  std::istringstream in([&] {
    try {
      return read_file(path, std::size_t{1} << 20, "solar spectra");
    } catch (const Error& e) {
      throw Error(e.status(), std::string(e.what()) + " (the solar spectrum; build the data folder: .ci/setup)");
    }
  }());
  std::vector<double> wl, irradiance;
  std::string line, source = "ASTM E-490-00a";
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    if (line[0] == '#') {
      if (line.rfind("# source:", 0) == 0) source = line.substr(10);
      continue;
    }
    std::istringstream s(line);
    double w = 0, e = 0;
    if (!(s >> w >> e) || !std::isfinite(w) || !std::isfinite(e) || e < 0)
      throw Error(Status::corrupt_file, path + ":" + std::to_string(n) + ": expected 'wavelength_um irradiance_W_cm2_um'");
    wl.push_back(w);
    irradiance.push_back(e);
  }
  // L_tab = E(1 au) / Omega_sun(1 au) (eq. 6).
  const double omega_1au = sun_projected_solid_angle_sr(constants::au_m);
  for (double& e : irradiance) e /= omega_1au;
  SpectrumTable t;
  t.entries_.push_back(NamedSpectrum{sun_spectrum, source, TabulatedFunction(wl, irradiance, path)});
  return t;
}

void SpectrumTable::add(const NamedSpectrum& spectrum) {
  if (spectrum.name.empty()) throw Error(Status::out_of_range, "spectrum.name: must not be empty");
  if (spectrum.name == sun_spectrum) throw Error(Status::not_allowed, "spectrum.name: 'sun' is the measured solar spectrum");
  const auto& values = spectrum.radiance_W_cm2_sr_um.values();
  for (std::size_t i = 0; i < values.size(); ++i)
    check_range(values[i], Range{0, max_spectral_radiance_W_cm2_sr_um},
                spectrum.name + ": radiance_W_cm2_sr_um[" + std::to_string(i) + "]", "W/(cm^2 sr um)");
  for (auto& e : entries_)
    if (e.name == spectrum.name) {
      e = spectrum;
      return;
    }
  entries_.push_back(spectrum);
}

const NamedSpectrum* SpectrumTable::find(const std::string& name) const {
  for (const auto& e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace eoir::universe
