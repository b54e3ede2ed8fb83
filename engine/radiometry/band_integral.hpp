// Band integrals over the sensor bandpass (spec 5.3, 5.4 eq. 29, 5.11.1
// eq. 48): the effective radiance L = int_low^high L_lambda RSR d lambda with
// the ideal RSR = 1 inside the band.
//
// Two ways to get it:
//  1. On the spectral sampling grid (what the engine does for arbitrary scene
//     spectra): the spec (5.3) defines N intervals of width
//     dl = (high - low) / N and the grid lambda_i = low + i dl, i = 0..N-1.
//     The integral is the rectangle sum  sum_i L(s_i) dl  where the sample
//     s_i of interval i is either
//       - interval_midpoint (default): s_i = lambda_i + dl/2, or
//       - interval_left_edge: s_i = lambda_i, the literal grid point of 5.3.
//     Both show the behaviour 7.3 demonstrates (an error at few intervals
//     that shrinks monotonically as N grows); left-edge error is first order
//     in dl (it is -13.4 % at N = 6 and still -0.82 % at N = 100 for a 150 K
//     blackbody in 8-12 um, where B rises steeply across the band), the
//     midpoint error is second order (-0.11 % at N = 6, -0.0004 % at
//     N = 100). The midpoint is the default because (a) spec 4.1.1 says each
//     of the N spectral values "corresponds to" one of the N wavelength
//     *intervals*, and the value that represents an interval in an integral is
//     the one at its centre; (b) 7.4.2 / 7.4.4 / 7.4.5 choose N = 50 "so that
//     errors in numerical integration over wavelength are minimized" and then
//     expect the exact 3.481e-4 W cm^-2 sr^-1 at 200 K to four digits, which
//     the midpoint sum gives (error 1e-5) and the left-edge sum does not
//     (-0.86 %). interval_left_edge stays available for anyone who wants the
//     literal 5.3 grid.
//  2. Exactly, for a pure Planck (or gray-body) term: the incomplete
//     Bose-Einstein integral, by series, independent of N (DESIGN.md 3).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/fidelity.hpp"

namespace eoir::radiometry {

// The rule is a fidelity knob (core/fidelity.hpp): interval_midpoint,
// s_i = low + (i + 1/2) dl, second order (default); interval_left_edge,
// s_i = low + i dl, the spec 5.3 grid verbatim, first order.
using eoir::SpectralQuadrature;
constexpr SpectralQuadrature kDefaultSpectralQuadrature = SpectralQuadrature::interval_midpoint;

// Spectral sampling grid of a band [low, high] um with N intervals (spec 5.3).
// Validates 0 < low < high (finite) and N >= 1; throws
// eoir::Error(out_of_range).
struct SpectralBand {
  double low_um = 0.0;
  double high_um = 0.0;
  std::int64_t intervals = 0;

  // dl = (high - low) / N [um].
  double interval_um() const;
  // lambda_i = low + i dl, i = 0..N-1: the spec 5.3 grid (left interval edges).
  double grid_wavelength_um(std::int64_t i) const;
  // The wavelength at which interval i is sampled under `rule`.
  double sample_wavelength_um(std::int64_t i, SpectralQuadrature rule = kDefaultSpectralQuadrature) const;
  // The spec 5.3 grid, N values.
  std::vector<double> grid_wavelengths_um() const;
  // All N sample wavelengths under `rule` (what the scene generator evaluates
  // its spectral radiance vectors at).
  std::vector<double> sample_wavelengths_um(SpectralQuadrature rule = kDefaultSpectralQuadrature) const;
  // Throws eoir::Error(out_of_range) naming the offending field.
  void validate() const;
};

// Rectangle sum  dl * sum_i values[i]  of N samples taken under any rule
// (the rule only decides where the samples were taken). Returns the
// band-integrated quantity, e.g. W cm^-2 sr^-1 for a spectral radiance
// vector in W cm^-2 sr^-1 um^-1. values.size() must equal band.intervals.
double integrate_spectral_samples(const SpectralBand& band, const std::vector<double>& values);
double integrate_spectral_samples(double interval_um, const double* values, std::size_t count) noexcept;

// Grid (numerical) band integral of B_lambda(T) over the band [W cm^-2 sr^-1]:
// what the engine reports for a blackbody scene with N intervals (7.3).
double grid_planck_band_radiance(double temperature_K, const SpectralBand& band,
                                 SpectralQuadrature rule = kDefaultSpectralQuadrature);

// The incomplete Bose-Einstein integrals of order 3 (dimensionless):
//   upper(x) = int_x^inf t^3 / (e^t - 1) dt,  lower(x) = int_0^x ...,
//   upper(x) + lower(x) = pi^4 / 15.
// upper: series sum_n e^{-n x} (x^3/n + 3x^2/n^2 + 6x/n^3 + 6/n^4) for x >= 1;
// lower: Bernoulli series sum_k B_k/k! x^{k+3}/(k+3) for x < 1 (converges for
// x < 2 pi; at x <= 1 the terms fall by (x / 2 pi)^2 per step). Both to
// ~1 ulp. x = +inf gives upper 0 / lower pi^4/15; x must be >= 0.
double bose_einstein_upper3(double x) noexcept;
double bose_einstein_lower3(double x) noexcept;

// Exact int_low^high B_lambda(T) d lambda [W cm^-2 sr^-1] for
// 0 <= low <= high <= +inf um (high = inf and low = 0 allowed: the total is
// sigma T^4 / pi). Computed as c1L T^4 / c2^4 * int_{x_hi}^{x_lo} t^3/(e^t-1)
// dt with x = c2 / (lambda T), choosing the series pair that avoids
// cancellation. T = 0 gives exactly 0. Throws eoir::Error(out_of_range) for T <
// 0, NaN or low > high.
double planck_band_radiance(double temperature_K, double low_um, double high_um);

// Gray body: eps * int B (eq. 4's eps_lambda B_lambda with wavelength-
// independent eps) [W cm^-2 sr^-1]. eps in [0, 1] (throws otherwise).
double gray_body_band_radiance(double emissivity, double temperature_K, double low_um, double high_um);

// Opaque gray body (spec 7.3: "Gray Body", reflectance set in %): by
// Kirchhoff's law eps = 1 - reflectance (both as fractions, 0..1; throws
// otherwise).
double emissivity_from_reflectance(double reflectance);

}  // namespace eoir::radiometry
