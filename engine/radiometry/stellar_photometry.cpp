#include "radiometry/stellar_photometry.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "radiometry/band_integral.hpp"
#include "radiometry/planck.hpp"

namespace eoir::radiometry {
namespace {

// Bessell (1990) PASP 102, 1181, Table 2, V column: 470..700 nm every 10 nm.
constexpr double kBessellVFirst_um = 0.470;
constexpr double kBessellVStep_um = 0.010;
constexpr double kBessellV[] = {0.000, 0.030, 0.163, 0.458, 0.780, 0.967, 1.000, 0.973, 0.898, 0.792, 0.684, 0.574,
                                0.461, 0.359, 0.270, 0.197, 0.135, 0.081, 0.045, 0.025, 0.017, 0.013, 0.009, 0.000};
constexpr int kBessellVCount = sizeof kBessellV / sizeof kBessellV[0];

// Passband mean of B(T) over the V response, by Gauss-Legendre quadrature on
// each 10 nm table interval (the response is linear there, B is smooth:
// 5 nodes are exact to ~1e-12 relative).
double v_passband_mean_planck(double temperature_K) {
  static const double xg[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                               0.9061798459386640};
  static const double wg[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                               0.2369268850561891};
  double weighted = 0.0, norm = 0.0;
  for (int i = 0; i + 1 < kBessellVCount; ++i) {
    const double a = kBessellVFirst_um + i * kBessellVStep_um;
    const double half = 0.5 * kBessellVStep_um;
    for (int j = 0; j < 5; ++j) {
      const double l = a + half * (1.0 + xg[j]);
      const double s = bessell_v_response(l);
      weighted += wg[j] * half * s * planck_radiance(l, temperature_K);
      norm += wg[j] * half * s;
    }
  }
  return weighted / norm;
}

}  // namespace

bool b_v_in_range(double b_v_mag) { return b_v_mag >= kMinBVForTemperature && b_v_mag <= kMaxBVForTemperature; }

double temperature_from_b_v(double b_v_mag) {
  require_finite(b_v_mag, "star.b_v");
  const double x = 0.92 * std::clamp(b_v_mag, kMinBVForTemperature, kMaxBVForTemperature);
  return 4600.0 * (1.0 / (x + 1.7) + 1.0 / (x + 0.62));  // Ballesteros (2012) eq. 14
}

double bessell_v_response(double wavelength_um) {
  const double u = (wavelength_um - kBessellVFirst_um) / kBessellVStep_um;
  if (!(u >= 0.0) || u >= kBessellVCount - 1) return 0.0;
  const int i = static_cast<int>(u);
  const double f = u - i;
  return kBessellV[i] * (1.0 - f) + kBessellV[i + 1] * f;
}

double m0_sr(double v_mag, double temperature_K, VZeroPoint zero_point) {
  require_finite(v_mag, "star.v_mag");
  require_positive(temperature_K, "star.temperature_K");
  const double target_W_cm2_um = kVZeroPointIrradiance_W_cm2_um * std::pow(10.0, -0.4 * v_mag);
  const double reference_radiance = zero_point == VZeroPoint::monochromatic_0p55um
                                        ? planck_radiance(kVReferenceWavelength_um, temperature_K)
                                        : v_passband_mean_planck(temperature_K);
  if (!(reference_radiance > 0.0))
    throw Error(Status::out_of_range, "star.temperature_K: too cold to emit in V");
  return target_W_cm2_um / reference_radiance;
}

double stellar_spectral_irradiance(double wavelength_um, double v_mag, double b_v_mag, VZeroPoint zero_point) {
  const double T = temperature_from_b_v(b_v_mag);
  return m0_sr(v_mag, T, zero_point) * planck_radiance(wavelength_um, T);
}

double stellar_band_irradiance(double low_um, double high_um, double v_mag, double b_v_mag, VZeroPoint zero_point) {
  const double T = temperature_from_b_v(b_v_mag);
  return m0_sr(v_mag, T, zero_point) * planck_band_radiance(T, low_um, high_um);
}

double v_passband_mean_irradiance(double v_mag, double b_v_mag, VZeroPoint zero_point) {
  const double T = temperature_from_b_v(b_v_mag);
  return m0_sr(v_mag, T, zero_point) * v_passband_mean_planck(T);
}

}  // namespace eoir::radiometry
