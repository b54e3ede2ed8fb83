#include "sensor/detector.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::sensor {
namespace {

// Uniform on [0, 1) from 53 bits of the generator.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// ln Gamma(x) for x >= 1: Stirling's series to x^-9 from x >= 7 (next term
// below 1e-12), Gamma(x) = Gamma(x + 1) / x below. (std::lgamma writes the
// global signgam: a data race between engines on threads.)
double log_gamma(double x) {
  double shift = 0.0;
  for (; x < 7.0; x += 1.0) shift -= std::log(x);
  const double r = 1.0 / x, r2 = r * r;
  const double series = r * (1.0 / 12 - r2 * (1.0 / 360 - r2 * (1.0 / 1260 - r2 * (1.0 / 1680 - r2 / 1188))));
  return shift + (x - 0.5) * std::log(x) - x + 0.91893853320467274178 + series;  // 0.5 ln(2 pi)
}

// An exact Poisson draw of mean m > 0. Below 10: inversion by sequential
// multiplication of uniforms (Knuth, TAOCP vol. 2, 3.4.1 F). From 10:
// Hoermann's transformed rejection with squeeze, PTRS (W. Hoermann, "The
// transformed rejection method for generating Poisson random variables",
// Insurance: Mathematics and Economics 12, 39-45, 1993), exact by its final
// test against the Poisson probability; about 1.1 uniform pairs per draw and
// no logarithm in 86 % of them.
double poisson(double m, std::mt19937_64& rng) {
  if (m < 10.0) {
    const double limit = std::exp(-m);
    double product = uniform01(rng), k = 0.0;
    while (product > limit) {
      product *= uniform01(rng);
      k += 1.0;
    }
    return k;
  }
  const double sm = std::sqrt(m);
  const double b = 0.931 + 2.53 * sm, a = -0.059 + 0.02483 * b;
  const double inv_alpha = 1.1239 + 1.1328 / (b - 3.4), vr = 0.9277 - 3.6224 / (b - 2.0);
  for (;;) {
    const double u = uniform01(rng) - 0.5, v = uniform01(rng);
    const double us = 0.5 - std::fabs(u);
    const double k = std::floor((2.0 * a / us + b) * u + m + 0.43);
    if (us >= 0.07 && v <= vr) return k;
    if (k < 0.0 || (us < 0.013 && v > us)) continue;
    if (std::log(v) + std::log(inv_alpha) - std::log(a / (us * us) + b) <= -m + k * std::log(m) - log_gamma(k + 1.0))
      return k;
  }
}

}  // namespace

DetectorPattern build_detector_pattern(const universe::DetectorParameters& p, std::int64_t pixels) {
  DetectorPattern out;
  const auto n = static_cast<std::size_t>(std::max<std::int64_t>(pixels, 0));
  out.response.resize(n);
  out.dark_current_e_s.resize(n);
  std::mt19937_64 rng(static_cast<std::uint64_t>(p.pattern_seed));
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    // Four draws per pixel whatever the settings, so that one knob does not
    // move the others' pattern.
    const double prnu = normal(rng), dsnu = normal(rng), hot = uniform(rng), dead = uniform(rng);
    out.response[i] = dead < p.dead_pixel_fraction ? 0.0 : std::max(0.0, 1.0 + p.prnu_fraction * prnu);
    out.dark_current_e_s[i] = hot < p.hot_pixel_fraction ? p.hot_pixel_dark_current_e_s
                                                         : std::max(0.0, p.dark_current_e_s + p.dsnu_e_s * dsnu);
  }
  return out;
}

std::uint32_t adc_max_adu(const universe::DetectorParameters& p) {
  return static_cast<std::uint32_t>((std::uint64_t{1} << p.adc_bits) - 1);
}

std::uint32_t adu_of_electrons(const universe::DetectorParameters& p, double electrons) {
  const double adu = std::floor(electrons / p.gain_e_per_adu + p.bias_adu + 0.5);
  const double top = static_cast<double>(adc_max_adu(p));
  if (!(adu > 0.0)) return 0;
  return static_cast<std::uint32_t>(std::min(adu, top));
}

std::uint32_t saturation_adu(const universe::DetectorParameters& p) { return adu_of_electrons(p, p.full_well_e); }

void apply_detector(const universe::DetectorParameters& p, const DetectorPattern& pattern,
                    const std::vector<double>& mean_electrons, double integration_time_s, bool noise,
                    std::mt19937_64& rng, std::vector<double>& electrons, std::vector<std::uint32_t>& adu) {
  const std::size_t n = mean_electrons.size();
  electrons.resize(n);
  adu.resize(n);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double well = p.full_well_e;
  // Past twice the full well (and 1000 e-) a Poisson draw falls below the
  // well with probability < exp(-125): the charge is the full well.
  const double certain_clip = 2.0 * well + 1000.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = mean_electrons[i] > 0.0 ? mean_electrons[i] : 0.0;  // NaN and rounding below 0: none
    const double mean = r * pattern.response[i] + pattern.dark_current_e_s[i] * integration_time_s;
    double q;
    if (mean >= certain_clip) q = well;
    else if (noise && mean > 0.0) q = std::min(poisson(mean, rng), well);
    else q = std::min(mean, well);
    const double e = noise && p.read_noise_e > 0.0 ? q + p.read_noise_e * normal(rng) : q;
    electrons[i] = e;
    adu[i] = adu_of_electrons(p, e);
  }
}

}  // namespace eoir::sensor
