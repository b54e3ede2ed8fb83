// One material as the sensor's spectral view sees it (spec 4.1.4.1, 5.3):
// its SRF as interval means on the view's grid, emissivity 1 - SRF, its BRDF
// (eq. 1), and its self-emission eps B(T) (eq. 4, eq. 5). Gray bodies keep
// the flat SRF of their reflectance property and, in exact band integration,
// the exact Planck band integral.
#pragma once
#include <memory>
#include <vector>

#include "radiometry/brdf.hpp"
#include "radiometry/spectral_view.hpp"
#include "universe/material.hpp"

namespace eoir::scene {

class SurfaceSpectrum {
 public:
  // `view` must outlive it. gray_reflectance is used for gray_body only.
  SurfaceSpectrum(const universe::Material& material, double gray_reflectance, const radiometry::SpectralView& view);
  bool gray() const { return gray_; }
  // SRF interval means on the view's grid (N values).
  const std::vector<double>& srf() const { return srf_; }
  // True if it reflects anything in the band (some SRF > 0).
  bool reflects() const { return reflects_; }
  // The largest SRF of the band (a scale of the SRF up to 1 / max_srf keeps it a reflectance).
  double max_srf() const { return max_srf_; }
  const radiometry::Brdf& brdf() const { return brdf_; }
  // Adds eps_lambda B_lambda(T) (W cm^-2 sr^-1 um^-1) at the view's
  // wavelengths to `out` (N values).
  void add_emission(double temperature_K, std::vector<double>& out) const;
  // Its band integral (eq. 48), W cm^-2 sr^-1.
  double emission_radiance(double temperature_K) const;
  // The same with its SRF scaled by s (emissivity 1 - s SRF, a land cover
  // under the brightness map): (1 - s) B(T) + s eps B(T) band-integrated, one
  // table look-up where both are tables (BandPlanckTable::blend).
  double scaled_emission_radiance(double scale, double temperature_K) const;
  // Its emission as scale x the weights of an L(T) table (eps = scale x
  // weights[i] at the grid's wavelengths: 1 - SRF, or a gray body's eps
  // times ones), for tables of that emission through a path; false where
  // the view integrates exactly (no grid sum to tabulate).
  bool emissivity(std::vector<double>& weights, double& scale) const;

 private:
  const radiometry::SpectralView* view_;
  bool gray_ = true;
  double gray_reflectance_ = 0.0;
  bool reflects_ = false;
  double max_srf_ = 0.0;
  std::vector<double> srf_;
  radiometry::Brdf brdf_;
  // emission_radiance's table, weights (1 - SRF) times the view's transmittance (grid integration, not gray).
  std::shared_ptr<const radiometry::BandPlanckTable> emission_table_;
};

}  // namespace eoir::scene
