#include "radiometry/band_integral.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "radiometry/planck.hpp"

namespace eoir::radiometry {

namespace {

constexpr double kPi4Over15 = constants::pi * constants::pi * constants::pi * constants::pi / 15.0;
// Where the two series hand over: upper needs ~40 terms at x = 1 (e^-40 <
// 2^-57), lower ~12 (the ratio of successive terms is ~(x / 2 pi)^2).
constexpr double kSplitX = 1.0;
// c1L / c2^4 [W cm^-2 sr^-1 K^-4]; times T^4 * (pi^4 / 15) it is sigma T^4 / pi.
constexpr double kBandPrefactor = c1L_W_um4_per_cm2_sr / (c2_um_K * c2_um_K * c2_um_K * c2_um_K);

// int_0^x t^3 / (e^t - 1) dt = sum_k (B_k / k!) x^(k+3) / (k+3), valid for
// x < 2 pi. kLowerCoeff[k] = B_k / (k! (k+3)) (Bernoulli numbers B_k with
// B_1 = -1/2; odd k > 1 vanish). Exact rationals, rounded to double.
constexpr double kLowerCoeff[] = {
    1.0 / 3.0,   // k = 0
    -1.0 / 8.0,  // k = 1
    1.0 / 60.0,  // k = 2:  (1/12)/5
    0.0,
    -1.0 / 5040.0,  // k = 4:  (-1/720)/7
    0.0,
    1.0 / 272160.0,  // k = 6:  (1/30240)/9
    0.0,
    -1.0 / 13305600.0,  // k = 8:  (-1/1209600)/11
    0.0,
    1.0 / 622702080.0,  // k = 10: (1/47900160)/13
    0.0,
    -3.52279342579166215e-11,  // k = 12: (-691/1307674368000)/15
    0.0,
    1.0 / 1270312243200.0,  // k = 14: (1/74724249600)/17
    0.0,
    -1.78404226122241216e-14,  // k = 16: (-3617/10670622842880000)/19
    0.0,
    4.08860097917992578e-16,  // k = 18: (43867/5109094217170944000)/21
    0.0,
    -9.45595086329592140e-18,  // k = 20: (-174611/802857662698291200000)/23
    0.0,
    2.20360113134409181e-19,  // k = 22: (77683/14101100039391805440000)/25
    0.0,
    -5.16832025400463853e-21,  // k = 24:
                               // (-236364091/1693824136731743669452800000)/27
};
constexpr int kLowerTerms = static_cast<int>(sizeof(kLowerCoeff) / sizeof(kLowerCoeff[0]));

// Lower series; intended for 0 <= x <= kSplitX.
double lower_series(double x) noexcept {
  double poly = 0.0;
  for (int k = kLowerTerms - 1; k >= 0; --k) poly = poly * x + kLowerCoeff[k];
  return x * x * x * poly;
}

// Upper series; intended for x >= kSplitX.
double upper_series(double x) noexcept {
  if (!(x < 746.0)) return 0.0;  // e^-x == 0 in double (and x^3 may overflow)
  const double q = std::exp(-x);
  const double x2 = x * x, x3 = x2 * x;
  double qn = 1.0, sum = 0.0;
  for (int n = 1; n <= 200; ++n) {
    qn *= q;
    if (qn == 0.0) break;
    const double dn = static_cast<double>(n);
    const double inv = 1.0 / dn;
    const double term = qn * inv * (x3 + inv * (3.0 * x2 + inv * (6.0 * x + inv * 6.0)));
    sum += term;
    if (term <= sum * 1e-18) break;
  }
  return sum;
}

}  // namespace

double bose_einstein_upper3(double x) noexcept {
  if (std::isnan(x) || x < 0.0) return std::numeric_limits<double>::quiet_NaN();
  return x >= kSplitX ? upper_series(x) : kPi4Over15 - lower_series(x);
}

double bose_einstein_lower3(double x) noexcept {
  if (std::isnan(x) || x < 0.0) return std::numeric_limits<double>::quiet_NaN();
  return x < kSplitX ? lower_series(x) : kPi4Over15 - upper_series(x);
}

// ---------------------------------------------------------------------------
// Spectral grid (spec 5.3)

void SpectralBand::validate() const {
  require_positive(low_um, "band low_um");
  require_positive(high_um, "band high_um");
  if (!(high_um > low_um))
    throw Error(Status::out_of_range,
                "band high_um (" + std::to_string(high_um) + ") must exceed low_um (" + std::to_string(low_um) + ")");
  if (intervals < 1)
    throw Error(Status::out_of_range, "spectral intervals must be >= 1, got " + std::to_string(intervals));
}

double SpectralBand::interval_um() const { return (high_um - low_um) / static_cast<double>(intervals); }

double SpectralBand::grid_wavelength_um(std::int64_t i) const {
  return low_um + static_cast<double>(i) * interval_um();
}

double SpectralBand::sample_wavelength_um(std::int64_t i, SpectralQuadrature rule) const {
  const double offset = rule == SpectralQuadrature::interval_midpoint ? 0.5 : 0.0;
  return low_um + (static_cast<double>(i) + offset) * interval_um();
}

std::vector<double> SpectralBand::grid_wavelengths_um() const {
  return sample_wavelengths_um(SpectralQuadrature::interval_left_edge);
}

std::vector<double> SpectralBand::sample_wavelengths_um(SpectralQuadrature rule) const {
  validate();
  std::vector<double> out(static_cast<std::size_t>(intervals));
  for (std::int64_t i = 0; i < intervals; ++i) out[static_cast<std::size_t>(i)] = sample_wavelength_um(i, rule);
  return out;
}

double integrate_spectral_samples(double interval_um, const double* values, std::size_t count) noexcept {
  // (four partial sums, added pairwise: a quarter of one sum's chain of
  // dependent additions, on every shaded sample)
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4)
    for (std::size_t k = 0; k < 4; ++k) sum[k] += values[i + k];
  for (std::size_t k = 0; i < count; ++i, ++k) sum[k] += values[i];
  return ((sum[0] + sum[1]) + (sum[2] + sum[3])) * interval_um;
}

double integrate_spectral_samples(const SpectralBand& band, const std::vector<double>& values) {
  band.validate();
  if (values.size() != static_cast<std::size_t>(band.intervals))
    throw Error(Status::out_of_range, "spectral vector has " + std::to_string(values.size()) +
                                          " values, the band has " + std::to_string(band.intervals) + " intervals");
  return integrate_spectral_samples(band.interval_um(), values.data(), values.size());
}

double grid_planck_band_radiance(double temperature_K, const SpectralBand& band, SpectralQuadrature rule) {
  band.validate();
  require_non_negative(temperature_K, "temperature_K");
  double sum = 0.0;
  for (std::int64_t i = 0; i < band.intervals; ++i)
    sum += planck_radiance(band.sample_wavelength_um(i, rule), temperature_K);
  return sum * band.interval_um();
}

// ---------------------------------------------------------------------------
// Exact band integral

double planck_band_radiance(double temperature_K, double low_um, double high_um) {
  require_non_negative(temperature_K, "temperature_K");
  require_non_negative(low_um, "band low_um");
  if (std::isnan(high_um) || !(high_um >= low_um))
    throw Error(Status::out_of_range,
                "band high_um (" + std::to_string(high_um) + ") must be >= low_um (" + std::to_string(low_um) + ")");
  if (temperature_K == 0.0 || high_um == low_um) return 0.0;
  // x decreases with lambda: x_lo belongs to the short-wave edge.
  const double x_lo = low_um == 0.0 ? std::numeric_limits<double>::infinity() : c2_um_K / (low_um * temperature_K);
  const double x_hi = std::isinf(high_um) ? 0.0 : c2_um_K / (high_um * temperature_K);
  double integral;  // int_{x_hi}^{x_lo} t^3 / (e^t - 1) dt
  if (x_hi >= kSplitX) {
    integral = upper_series(x_hi) - upper_series(x_lo);
  } else if (x_lo <= kSplitX) {
    integral = lower_series(x_lo) - lower_series(x_hi);
  } else {
    integral = (lower_series(kSplitX) - lower_series(x_hi)) + (upper_series(kSplitX) - upper_series(x_lo));
  }
  const double t2 = temperature_K * temperature_K;
  return kBandPrefactor * t2 * t2 * integral;
}

double emissivity_from_reflectance(double reflectance) {
  if (!(reflectance >= 0.0 && reflectance <= 1.0))
    throw Error(Status::out_of_range, "reflectance must be in [0, 1], got " + std::to_string(reflectance));
  return 1.0 - reflectance;
}

double gray_body_band_radiance(double emissivity, double temperature_K, double low_um, double high_um) {
  if (!(emissivity >= 0.0 && emissivity <= 1.0))
    throw Error(Status::out_of_range, "emissivity must be in [0, 1], got " + std::to_string(emissivity));
  return emissivity * planck_band_radiance(temperature_K, low_um, high_um);
}

}  // namespace eoir::radiometry
