// The aerosol's spectral optics (Shettle and Fenn 1979 as LOWTRAN 7
// tabulates them, data/atmosphere/aerosol_shettle_fenn_1979.csv):
// extinction per unit 0.55 um extinction, single-scattering albedo and the
// Henyey-Greenstein asymmetry g against wavelength, for one model at one
// relative humidity (ln of each coefficient linear in ln(100 - RH) between
// the tabulated 0, 70, 80, 99 %, as LOWTRAN interpolates; linear in
// wavelength between the 47 tabulated wavelengths).
#pragma once
#include <string>
#include <vector>

namespace eoir::atmosphere {

struct AerosolOptics {
  double extinction_per_550 = 0;  // extinction / extinction at 0.55 um
  double single_scatter_albedo = 0;
  double asymmetry = 0;
};

class AerosolSpectra {
 public:
  // model: "rural", "urban", "maritime" or "tropospheric". Throws io or
  // corrupt_file naming the file and line, unknown_name for a model.
  static AerosolSpectra load(const std::string& data_dir, const std::string& model, double relative_humidity_pct);
  AerosolOptics at(double wavelength_um) const;

 private:
  std::vector<double> wavelength_um_, extinction_, absorption_, asymmetry_;
};

// The Henyey-Greenstein phase function (normalised to 4 pi) of asymmetry g
// at the cosine of the scattering angle: (1 - g^2) / (1 + g^2 - 2 g cos)^1.5.
double henyey_greenstein_phase(double g, double cos_scattering);

// Relative humidity (%) of water vapour of number density h2o_m3 at
// temperature T (Buck 1981 saturation pressure over water).
double relative_humidity_pct(double h2o_m3, double temperature_K);

}  // namespace eoir::atmosphere
