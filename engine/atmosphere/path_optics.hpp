// A path's transmittance per spectral interval of a sensor's band (spec
// 4.1.5.3 eq. 9's T_in and T_out; 4.3.1.1): Rayleigh scattering (Bodhaine et
// al. 1999) of the path's air, the aerosol's extinction (its 0.55 um optical
// depth times the Shettle and Fenn spectrum of the boundary-layer model below
// 2 km and of the tropospheric model above, at the profile's ground
// humidity and 70 %, as LOWTRAN 7 does), and the absorbers' (band models,
// molecular_absorption.hpp). Made once per atmosphere and band; each interval
// is the mean of its sub-samples' transmittances, spaced at most
// kSubSampleSpacing_cm1 apart in wavenumber (the band models' 20 cm^-1
// resolution: finer sampling adds nothing they resolve; the fidelity knob
// atmosphere_sub_sample_spacing_cm1).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "atmosphere/aerosol_optics.hpp"
#include "atmosphere/profile.hpp"
#include "atmosphere/shell_path.hpp"
#include "radiometry/band_integral.hpp"

namespace eoir::atmosphere {

class MolecularAbsorption;

constexpr double kSubSampleSpacing_cm1 = 20.0;

// Eq. 9's path terms along one path, per spectral interval: what does not
// depend on where the light sources are.
struct PathTerms {
  std::vector<double> transmittance;  // T_out from the path's far end to its first point
  std::vector<double> thermal;        // L_path: the path's own emission toward its first point
  // Single scatter (eq. 9's L_scatter, Nishita et al. 1993) per segment
  // (from the first point out) and interval: of the light that the
  // segment's air (Rayleigh) and aerosol scatter per unit phase function
  // (normalised to 4 pi), the fraction that reaches the first point:
  // (T(0, near) - T(0, far)) tau_scatter / tau_extinction of the segment,
  // so that a segment thick with absorbers scatters less. The aerosol's
  // Henyey-Greenstein asymmetry g (scatter-weighted).
  std::vector<std::vector<double>> rayleigh, aerosol, asymmetry;
};

// What a path's transmittance is made of: per interval, its sub-samples' mean optical depths.
struct OpticalDepths {
  std::vector<double> rayleigh, aerosol, absorption;  // per interval, the sub-samples' means
};

class PathOptics {
 public:
  PathOptics(std::shared_ptr<const AtmosphereProfile> profile, const universe::AtmosphereSettings& settings,
             const std::string& data_dir, const radiometry::SpectralBand& band,
             double sub_sample_spacing_cm1 = kSubSampleSpacing_cm1);
  ~PathOptics();
  const radiometry::SpectralBand& band() const { return band_; }
  const AtmosphereProfile& profile() const { return *profile_; }
  const std::shared_ptr<const AtmosphereProfile>& profile_ptr() const { return profile_; }
  // The sub-sample wavelengths (um), interval by interval: interval i holds
  // [first_[i], first_[i + 1]).
  const std::vector<double>& sub_wavelengths_um() const { return wavelength_um_; }
  std::size_t sub_samples() const { return wavelength_um_.size(); }
  // Mean transmittance of each interval along the path (out: one per interval).
  void transmittance(const PathColumns& path, std::vector<double>& out) const;
  // The optical depths of each interval (means over its sub-samples).
  OpticalDepths optical_depths(const PathColumns& path) const;
  // The path's own thermal emission toward its first point (eq. 9's L_path,
  // W cm^-2 sr^-1 um^-1 per interval): Schwarzschild's equation layer by
  // layer, sum over segments of B(T_segment) (T(0, k) - T(0, k + 1)), T(0, k)
  // the transmittance from the first point to the k-th segment's near end
  // (so the segments must run from the observer outward). The extinction of
  // scattering (Rayleigh, the aerosol's single-scatter albedo) is counted as
  // emitting too: in 8-12 um about 1 % of L_path for a rural aerosol.
  void path_radiance(const PathColumns& path, std::vector<double>& out) const;
  // T_out, L_path (thermal) and the single-scatter weights in one pass
  // over the path's segments (which must run from the first point out).
  PathTerms terms(const PathColumns& path) const;

 private:
  // Transmittance at every sub-sample.
  void sub_transmittance(const PathColumns& path, std::vector<double>& out) const;
  // Optical depth at every sub-sample.
  void sub_depths(const PathColumns& path, std::vector<double>& rayleigh, std::vector<double>& aerosol,
                  std::vector<double>& absorption) const;
  std::shared_ptr<const AtmosphereProfile> profile_;
  radiometry::SpectralBand band_;
  std::vector<std::size_t> first_;  // per interval, its first sub-sample; one more at the end
  std::vector<double> wavelength_um_;
  std::vector<double> rayleigh_m2_;          // cross section per air molecule
  std::vector<double> boundary_per_550_, background_per_550_;  // aerosol extinction / extinction at 0.55 um
  std::vector<double> boundary_albedo_, background_albedo_;    // the aerosols' single-scatter albedo
  std::vector<double> boundary_g_, background_g_;              // and asymmetry
  std::unique_ptr<const MolecularAbsorption> molecules_;
};

}  // namespace eoir::atmosphere
