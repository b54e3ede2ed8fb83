#include "sensor/detector.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::sensor {

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
  std::poisson_distribution<long long> poisson;
  using PoissonParam = std::poisson_distribution<long long>::param_type;
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
    else if (noise && mean > 0.0) q = std::min(static_cast<double>(poisson(rng, PoissonParam(mean))), well);
    else q = std::min(mean, well);
    const double e = noise && p.read_noise_e > 0.0 ? q + p.read_noise_e * normal(rng) : q;
    electrons[i] = e;
    adu[i] = adu_of_electrons(p, e);
  }
}

}  // namespace eoir::sensor
