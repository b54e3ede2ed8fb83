// The sensor's spectral view (spec 4.1.1, 5.3): the band, the N wavelengths
// at which the scene generator evaluates its spectral radiance vectors, and
// how it integrates them over the band (eq. 48, RSR = 1 in band).
#pragma once
#include <memory>
#include <vector>

#include "core/fidelity.hpp"
#include "radiometry/band_integral.hpp"
#include "radiometry/band_planck_table.hpp"

namespace eoir::radiometry {

struct SpectralView {
  SpectralBand band;
  BandIntegration integration = BandIntegration::grid;
  SpectralQuadrature quadrature = SpectralQuadrature::interval_midpoint;
  std::vector<double> sample_wavelengths_um;  // where spectral vectors are evaluated
  double interval_um = 0.0;  // band.interval_um(), set by make (integrate's weight: no division per call)
  // The black body's band radiance on the grid (grid integration), shared by
  // copies of the view and every gray body.
  std::shared_ptr<const BandPlanckTable> black_body;
  // A path's transmittance per interval, weighting every band integral (eq.
  // 9's T_out inside eq. 48); empty: none (vacuum).
  std::vector<double> transmittance;

  // Validates the band (throws eoir::Error naming the field).
  static SpectralView make(double low_um, double high_um, std::int64_t intervals, BandIntegration integration,
                           SpectralQuadrature quadrature);
  // The same view seen through a path of transmittance T (one value per
  // interval): grid integration (the exact Planck series has no weights).
  static SpectralView through(const SpectralView& view, std::vector<double> transmittance);
  // Band integral (eq. 48) of a spectral vector sampled at sample_wavelengths_um
  // (weighted by the transmittance, if any).
  double integrate(const std::vector<double>& spectral_values) const;
  // eps B_lambda(T) of an opaque gray body of reflectance `reflectance`
  // (eq. 4's self-emission, emissivity 1 - SRF, spec 4.1.4.1): the spectral
  // vector added to `out` (one value per sample wavelength), and its band
  // integral (exact when the view says so).
  void add_gray_body_spectrum(double temperature_K, double reflectance, std::vector<double>& out) const;
  double gray_body_radiance(double temperature_K, double reflectance) const;
};

}  // namespace eoir::radiometry
