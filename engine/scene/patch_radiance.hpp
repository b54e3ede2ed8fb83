// Radiance leaving a surface toward the sensor (spec 4.1.5.3, eq. 4). This
// issue models self-emission, eps_lambda B_lambda(T) with eps = 1 - SRF for
// gray bodies (spec 4.1.4.1); the reflected-source and background terms of
// eq. 4 are added here later, as further terms of the same sum.
#pragma once
#include <vector>

#include "radiometry/band_integral.hpp"

namespace eoir::scene {

// What the radiance of a surface point depends on.
struct SurfacePoint {
  double temperature_K = 0.0;
  double reflectance = 0.0;  // gray-body SRF
};

enum class BandIntegration { grid, exact };

// The sensor's spectral view: band, grid, and how to integrate it.
struct SpectralView {
  radiometry::SpectralBand band;
  BandIntegration integration = BandIntegration::grid;
  std::vector<double> sample_wavelengths_um;  // where spectral vectors are evaluated
  static SpectralView make(double low_um, double high_um, std::int64_t intervals, BandIntegration integration);
};

// Spectral radiance vector L_lambda (W cm^-2 sr^-1 um^-1) at the view's
// sample wavelengths (eq. 4, self-emission term).
std::vector<double> spectral_radiance(const SurfacePoint& s, const SpectralView& view);
// Effective radiance (eq. 48, RSR = 1 in band), W cm^-2 sr^-1.
double effective_radiance(const SurfacePoint& s, const SpectralView& view);

}  // namespace eoir::scene
