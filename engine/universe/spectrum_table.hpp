// The table of tabulated spectral radiances (spec 4.1.4): measured spectra
// that stand for an object's self-radiance instead of eps B(T). Entry 0 is
// the Sun, ASTM E-490 (spec 4.1.4, eq. 6: E_sun = L_tab dOmega_sun): the
// irradiance at 1 au divided by the projected solid angle of the Sun's disc
// at 1 au.
// Users add their own (plumes later).
#pragma once
#include <string>
#include <vector>

#include "core/tabulated_function.hpp"

namespace eoir::universe {

// IAU 2015 nominal solar radius and 1 au (m).
constexpr double sun_radius_m = 695700.0e3;

struct NamedSpectrum {
  std::string name;
  std::string source;
  TabulatedFunction radiance_W_cm2_sr_um;
};

constexpr const char* sun_spectrum = "sun";
// Largest tabulated spectral radiance, W/(cm^2 sr um): above a 1e6 K
// blackbody at 0.28 um (1.4e8, object_bounds' hottest), so every image sum
// stays finite.
constexpr double max_spectral_radiance_W_cm2_sr_um = 1.0e10;

class SpectrumTable {
 public:
  // Reads the data folder's solar/e490.txt (throws io naming the path,
  // corrupt_file naming the line).
  static SpectrumTable load(const std::string& data_dir);
  // Adds or replaces a user spectrum (never "sun"); validates.
  void add(const NamedSpectrum& spectrum);
  const NamedSpectrum* find(const std::string& name) const;
  const NamedSpectrum& sun() const { return entries_.front(); }
  const std::vector<NamedSpectrum>& entries() const { return entries_; }
  // The user's entries (1..), for saving.
  std::vector<NamedSpectrum> user_entries() const { return {entries_.begin() + 1, entries_.end()}; }

 private:
  std::vector<NamedSpectrum> entries_;  // [0] the Sun
};

// The projected solid angle (sr) of the Sun's disc at distance d, pi sin^2
// rho with sin rho = R_sun / d (eq. 6's dOmega_sun: a uniform disc of
// radiance L gives the irradiance L pi sin^2 rho on a surface facing it, so
// E_sun = E(1 au) (1 au / d)^2 exactly).
double sun_projected_solid_angle_sr(double distance_m);

}  // namespace eoir::universe
