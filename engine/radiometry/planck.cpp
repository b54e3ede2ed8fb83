#include "radiometry/planck.hpp"

#include <cmath>
#include <limits>

namespace eoir::radiometry {

namespace {
// Beyond this x the Bose-Einstein factor 1/(e^x - 1) equals e^-x to double
// precision (e^-40 < 2^-57), and exp(+x) would eventually overflow.
constexpr double kWienRegionX = 40.0;
// exp(-x) is exactly 0 in double beyond ~745.13; stop there.
constexpr double kUnderflowX = 746.0;
}  // namespace

double planck_x(double wavelength_um, double temperature_K) noexcept {
  if (std::isnan(wavelength_um) || std::isnan(temperature_K)) return std::numeric_limits<double>::quiet_NaN();
  if (!(temperature_K > 0.0) || !(wavelength_um > 0.0)) return std::numeric_limits<double>::infinity();
  return c2_um_K / (wavelength_um * temperature_K);
}

double planck_radiance(double wavelength_um, double temperature_K) noexcept {
  if (std::isnan(wavelength_um) || std::isnan(temperature_K)) return std::numeric_limits<double>::quiet_NaN();
  if (!(temperature_K > 0.0) || !(wavelength_um > 0.0)) return 0.0;
  if (std::isinf(wavelength_um)) return 0.0;  // Rayleigh-Jeans: ~ lambda^-4 -> 0
  // lambda * T may overflow to inf (huge lambda and T): x -> 0 correctly.
  const double x = c2_um_K / (wavelength_um * temperature_K);
  if (x >= kUnderflowX) return 0.0;
  // lambda^-5 as a product of reciprocals so that large lambda underflows
  // rather than forming lambda^5 = inf first (same value, no overflow).
  const double inv = 1.0 / wavelength_um;
  const double inv2 = inv * inv;
  const double prefactor = c1L_W_um4_per_cm2_sr * inv2 * inv2 * inv;
  if (x > kWienRegionX) {
    // Wien limit: prefactor may be huge at tiny lambda while e^-x is tiny;
    // combine in the log domain when the product could overflow.
    const double e = std::exp(-x);
    if (std::isinf(prefactor)) return std::exp(std::log(c1L_W_um4_per_cm2_sr) - 5.0 * std::log(wavelength_um) - x);
    return prefactor * e;
  }
  // lambda * T overflowed (far outside the physical domain): Rayleigh-Jeans.
  if (x == 0.0) return c1L_W_um4_per_cm2_sr / c2_um_K * inv2 * inv2 * temperature_K;
  return prefactor / std::expm1(x);
}

void planck_radiance(double temperature_K, const double* wavelength_um, double* out, std::size_t count) noexcept {
  for (std::size_t i = 0; i < count; ++i) out[i] = planck_radiance(wavelength_um[i], temperature_K);
}

std::vector<double> planck_radiance(double temperature_K, const std::vector<double>& wavelength_um) {
  std::vector<double> out(wavelength_um.size());
  planck_radiance(temperature_K, wavelength_um.data(), out.data(), out.size());
  return out;
}

void add_gray_body_radiance(double emissivity, double temperature_K, const double* wavelength_um, double* accumulator,
                            std::size_t count) noexcept {
  if (emissivity == 0.0) return;
  for (std::size_t i = 0; i < count; ++i)
    accumulator[i] += emissivity * planck_radiance(wavelength_um[i], temperature_K);
}

}  // namespace eoir::radiometry
