// Planck spectral radiance, spec 4.1.5.3 eq. 5, in the spec's units
// (spec 4.1.1): W cm^-2 sr^-1 um^-1 with the wavelength in um.
//
//   B_lambda(T) = 2 h c^2 / lambda^5 * 1 / (exp(h c / (lambda k T)) - 1)
//
// Numerics (DESIGN.md section 3):
//  - the denominator is std::expm1(x), x = c2 / (lambda T), so the
//    Rayleigh-Jeans end (x -> 0, e.g. 28 um at 1e6 K) keeps full precision;
//  - the Wien end (x large, e.g. 0.28 um at 3 K) is evaluated as
//    c1 lambda^-5 e^-x without forming exp(+x), so it underflows gracefully
//    to (sub)normal numbers and finally 0; never inf or NaN;
//  - T = 0 gives exactly 0 (and so does T < 0, which is unphysical).
// Valid for any lambda in (0, inf) and T in [0, inf) where lambda^-5 itself
// is representable (lambda > ~1e-61 um); the tested domain is lambda
// 1e-3 .. 1e4 um and T 0 .. 1e6 K. NaN inputs give NaN.
#pragma once
#include <cstddef>
#include <vector>

#include "core/constants.hpp"

namespace eoir::radiometry {

// First radiation constant for radiance, c1L = 2 h c^2, expressed so that
// c1L / lambda_um^5 is in W cm^-2 sr^-1 um^-1:
// 2 h c^2 [W m^2 sr^-1] * 1e24 um^4/m^4 * 1e-4 m^2/cm^2 = 1.191042972e4.
constexpr double c1L_W_um4_per_cm2_sr =
    2.0 * constants::planck_J_s * constants::speed_of_light_m_per_s * constants::speed_of_light_m_per_s * 1.0e20;
// Second radiation constant c2 = h c / k in um K (14387.768775...).
constexpr double c2_um_K =
    constants::planck_J_s * constants::speed_of_light_m_per_s / constants::boltzmann_J_per_K * 1.0e6;
// Stefan-Boltzmann constant sigma = 2 pi^5 k^4 / (15 h^3 c^2) in W cm^-2 K^-4
// (5.670374419e-12; derived here from the exact SI h, c, k).
constexpr double stefan_boltzmann_W_per_cm2_K4 = c1L_W_um4_per_cm2_sr / (c2_um_K * c2_um_K * c2_um_K * c2_um_K) *
                                                 constants::pi * constants::pi * constants::pi * constants::pi *
                                                 constants::pi / 15.0;
// Wien displacement constant b = c2 / x_w with x_w = 5 (1 - e^-x_w), in um K
// (2897.771955...).
constexpr double wien_displacement_um_K = c2_um_K / 4.965114231744276303;

// x = h c / (lambda k T); +inf for T <= 0.
double planck_x(double wavelength_um, double temperature_K) noexcept;

// B_lambda(T) of eq. 5 [W cm^-2 sr^-1 um^-1]. 0 for T <= 0 or lambda <= 0.
double planck_radiance(double wavelength_um, double temperature_K) noexcept;

// Gray body eps * B_lambda(T) (eq. 4's self-radiance term)
// [W cm^-2 sr^-1 um^-1].
inline double gray_body_radiance(double emissivity, double wavelength_um, double temperature_K) noexcept {
  return emissivity * planck_radiance(wavelength_um, temperature_K);
}

// Vectorised eq. 5 over a spectral grid: out[i] = B(wavelength_um[i], T),
// i < count. out may alias wavelength_um (in-place evaluation is allowed).
void planck_radiance(double temperature_K, const double* wavelength_um, double* out, std::size_t count) noexcept;
std::vector<double> planck_radiance(double temperature_K, const std::vector<double>& wavelength_um);

// Adds emissivity * B(wavelength_um[i], T) to accumulator[i] (the eq. 4
// self-radiance term added onto a reflected-radiance vector).
void add_gray_body_radiance(double emissivity, double temperature_K, const double* wavelength_um, double* accumulator,
                            std::size_t count) noexcept;

}  // namespace eoir::radiometry
