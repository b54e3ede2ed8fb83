// The detector stage after eq. 55 (sensor/detector.hpp; beyond spec 5,
// issue 23 item 4), checked against what a detector engineer measures on a
// real sensor: the photon transfer curve of flat-field pairs returns the
// conversion gain, a dark-frame series the dark current, and the ADU clip at
// the full well and at 2^bits - 1. Expected values are the configured
// parameters and closed forms (Poisson probabilities); tolerances are stated
// with their statistical margin.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "sensor/detector.hpp"
#include "universe/sensor_parameters.hpp"

namespace {
using eoir::sensor::apply_detector;
using eoir::sensor::build_detector_pattern;
using eoir::sensor::DetectorPattern;
using eoir::universe::DetectorParameters;

constexpr std::int64_t kPixels = 512 * 256;

struct Frame {
  std::vector<double> electrons;
  std::vector<std::uint32_t> adu;
};

Frame expose(const DetectorParameters& p, const DetectorPattern& pattern, double mean_e, double t_s,
             std::mt19937_64& rng, bool noise = true) {
  Frame f;
  apply_detector(p, pattern, std::vector<double>(kPixels, mean_e), t_s, noise, rng, f.electrons, f.adu);
  return f;
}

double mean_of(const std::vector<std::uint32_t>& v) {
  double s = 0;
  for (std::uint32_t x : v) s += x;
  return s / static_cast<double>(v.size());
}

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += x[i], my += y[i];
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(y.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
  return sxy / sxx;
}

// Photon transfer curve (Janesick, Photon Transfer, SPIE 2007, ch. 4): for
// pairs of flats at one level, var(A - B) / 2 = S / g + (read noise / g)^2
// + 1/12 in ADU^2, S the bias-subtracted mean in ADU; differencing removes
// the fixed pattern (PRNU). The slope of variance against mean is 1 / g.
TEST(Detector, PhotonTransferCurveReturnsTheGainWithinOnePercent) {
  DetectorParameters p;
  p.enabled = true;
  p.gain_e_per_adu = 2.7;
  p.read_noise_e = 6.0;
  p.bias_adu = 500.0;
  p.full_well_e = 150000.0;
  p.adc_bits = 16;
  p.prnu_fraction = 0.01;
  p.dark_current_e_s = 5.0;
  p.dsnu_e_s = 1.0;
  const DetectorPattern pattern = build_detector_pattern(p, kPixels);
  std::mt19937_64 rng(20261126);
  std::vector<double> means, variances;
  for (double level_e : {2000.0, 5000.0, 10000.0, 20000.0, 35000.0, 50000.0, 70000.0, 90000.0}) {
    // Two pairs of flats per level.
    double mean = 0, variance = 0;
    for (int pair = 0; pair < 2; ++pair) {
      const Frame a = expose(p, pattern, level_e, 1.0, rng), b = expose(p, pattern, level_e, 1.0, rng);
      double sum = 0, sum2 = 0;
      for (std::int64_t i = 0; i < kPixels; ++i) {
        const double d = static_cast<double>(a.adu[i]) - static_cast<double>(b.adu[i]);
        sum += d;
        sum2 += d * d;
      }
      const double n = static_cast<double>(kPixels);
      variance += 0.25 * (sum2 - sum * sum / n) / (n - 1);
      mean += 0.25 * (mean_of(a.adu) + mean_of(b.adu));
    }
    means.push_back(mean - p.bias_adu);
    variances.push_back(variance);
  }
  // Each variance has a relative standard error of sqrt(1 / n) = 0.28 %
  // (two pairs); the gain over eight levels about 0.2 % (0.3 % with one
  // pair, simulated over seeds): 1 % is five sigma.
  const double gain = 1.0 / slope(means, variances);
  std::printf("photon transfer gain %.5f e-/ADU (configured %.5f): %+.3f %%\n", gain, p.gain_e_per_adu,
              100.0 * (gain / p.gain_e_per_adu - 1.0));
  EXPECT_NEAR(gain, p.gain_e_per_adu, 0.01 * p.gain_e_per_adu);
}

// Dark frames at several integration times: the mean bias-subtracted signal
// times the gain grows as D t (DSNU averages out over the pixels:
// 1 e-/s / sqrt(n) = 0.003 e-/s).
TEST(Detector, DarkFrameSeriesReturnsTheDarkCurrentWithinOnePercent) {
  DetectorParameters p;
  p.enabled = true;
  p.gain_e_per_adu = 1.6;
  p.read_noise_e = 4.0;
  p.bias_adu = 1000.0;
  p.full_well_e = 100000.0;
  p.dark_current_e_s = 12.5;
  p.dsnu_e_s = 1.0;
  p.prnu_fraction = 0.02;
  const DetectorPattern pattern = build_detector_pattern(p, kPixels);
  std::mt19937_64 rng(7);
  std::vector<double> times, signals;
  for (double t_s : {1.0, 2.0, 5.0, 10.0, 30.0, 60.0}) {
    const Frame dark = expose(p, pattern, 0.0, t_s, rng);
    times.push_back(t_s);
    signals.push_back((mean_of(dark.adu) - p.bias_adu) * p.gain_e_per_adu);
  }
  const double dark = slope(times, signals);
  std::printf("dark current %.5f e-/s (configured %.5f): %+.3f %%\n", dark, p.dark_current_e_s,
              100.0 * (dark / p.dark_current_e_s - 1.0));
  EXPECT_NEAR(dark, p.dark_current_e_s, 0.01 * p.dark_current_e_s);
}

// Exact Poisson at low counts: with 0.7 e- per pixel and no read noise the
// fraction of pixels with 0, 1 and 2 electrons is exp(-m) m^k / k!
// (a Gaussian of the same mean and variance would put 28 % below -0.5 e-).
TEST(Detector, PhotonNoiseIsPoissonAtLowCounts) {
  DetectorParameters p;
  p.enabled = true;
  p.bias_adu = 0.0;
  const DetectorPattern pattern = build_detector_pattern(p, kPixels);
  std::mt19937_64 rng(11);
  const double m = 0.7;
  const Frame f = expose(p, pattern, m, 1.0, rng);
  std::vector<double> count(4, 0.0);
  for (double e : f.electrons) {
    ASSERT_EQ(e, std::floor(e));  // whole electrons
    if (e < 4) count[static_cast<std::size_t>(e)] += 1;
  }
  const double n = static_cast<double>(kPixels);
  double factorial = 1;
  for (int k = 0; k < 4; ++k) {
    if (k > 0) factorial *= k;
    const double expected = std::exp(-m) * std::pow(m, k) / factorial;
    // Five binomial standard errors.
    EXPECT_NEAR(count[static_cast<std::size_t>(k)] / n, expected, 5 * std::sqrt(expected * (1 - expected) / n))
        << "k = " << k;
  }
}

// Exact Poisson above the inversion branch (transformed rejection from 10
// e-): at means 10 and 25 the fraction of pixels with each count from m - 2
// sigma to m + 2 sigma is exp(-m) m^k / k!, and at 1e4 the mean and variance
// are m (five standard errors each: variance s.e. m sqrt(2 / n)).
TEST(Detector, PhotonNoiseIsPoissonAtMeanCounts) {
  DetectorParameters p;
  p.enabled = true;
  p.bias_adu = 0.0;
  p.full_well_e = 1.0e6;
  const DetectorPattern pattern = build_detector_pattern(p, kPixels);
  std::mt19937_64 rng(13);
  const double n = static_cast<double>(kPixels);
  for (double m : {10.0, 25.0}) {
    const Frame f = expose(p, pattern, m, 1.0, rng);
    std::vector<double> count(100, 0.0);
    for (double e : f.electrons)
      if (e < 100) count[static_cast<std::size_t>(e)] += 1;
    const int lo = static_cast<int>(m - 2 * std::sqrt(m)), hi = static_cast<int>(m + 2 * std::sqrt(m));
    for (int k = lo; k <= hi; ++k) {
      const double expected = std::exp(-m + k * std::log(m) - std::lgamma(k + 1.0));
      EXPECT_NEAR(count[static_cast<std::size_t>(k)] / n, expected, 5 * std::sqrt(expected * (1 - expected) / n))
          << "m = " << m << ", k = " << k;
    }
  }
  const double m = 1.0e4;
  const Frame f = expose(p, pattern, m, 1.0, rng);
  double sum = 0, sum2 = 0;
  for (double e : f.electrons) sum += e, sum2 += e * e;
  const double mean = sum / n, variance = (sum2 - sum * mean) / (n - 1);
  EXPECT_NEAR(mean, m, 5 * std::sqrt(m / n));
  EXPECT_NEAR(variance, m, 5 * m * std::sqrt(2.0 / n));
}

// Clipping: charge at the full well, ADU at 2^bits - 1 (and never below 0).
TEST(Detector, ClipsAtTheFullWellAndAtTheLargestAdu) {
  DetectorParameters p;
  p.enabled = true;
  p.gain_e_per_adu = 1.0;
  p.bias_adu = 100.0;
  p.full_well_e = 50000.0;
  p.adc_bits = 16;
  const DetectorPattern pattern = build_detector_pattern(p, kPixels);
  std::mt19937_64 rng(3);
  // 1.2 full wells (Poisson sigma 245 e-, 40 sigma above the well): every
  // pixel holds the full well, ADU = 50000 / 1 + 100.
  Frame f = expose(p, pattern, 60000.0, 1.0, rng);
  for (std::int64_t i = 0; i < kPixels; ++i) {
    ASSERT_EQ(f.electrons[i], 50000.0);
    ASSERT_EQ(f.adu[i], 50100u);
  }
  EXPECT_EQ(eoir::sensor::saturation_adu(p), 50100u);
  // A gain of 0.5 e-/ADU maps the full well to 100100 ADU: the 16-bit ADC
  // clips at 65535; a 12-bit one at 4095.
  p.gain_e_per_adu = 0.5;
  f = expose(p, pattern, 60000.0, 1.0, rng);
  for (std::uint32_t a : f.adu) ASSERT_EQ(a, 65535u);
  EXPECT_EQ(eoir::sensor::saturation_adu(p), 65535u);
  p.adc_bits = 12;
  f = expose(p, pattern, 3000.0, 1.0, rng);
  for (std::uint32_t a : f.adu) ASSERT_EQ(a, 4095u);
  p.adc_bits = 32;
  EXPECT_EQ(eoir::sensor::adc_max_adu(p), 4294967295u);
  // Bias 0 and read noise: negative readouts clip at 0 ADU.
  p.adc_bits = 16;
  p.bias_adu = 0.0;
  p.read_noise_e = 10.0;
  f = expose(p, pattern, 0.0, 1.0, rng);
  std::int64_t zeros = 0;
  for (std::int64_t i = 0; i < kPixels; ++i) zeros += f.adu[i] == 0;
  // P(e / 0.5 < 0.5) = P(N(0, 10) < 0.25) = 0.51.
  EXPECT_NEAR(static_cast<double>(zeros) / kPixels, 0.51, 0.01);
}

// The fixed pattern: from the seed alone, hot and dead pixels at their
// fractions (five binomial standard errors), the same for every frame.
TEST(Detector, FixedPatternFromTheSeed) {
  DetectorParameters p;
  p.enabled = true;
  p.hot_pixel_fraction = 0.002;
  p.dead_pixel_fraction = 0.001;
  p.hot_pixel_dark_current_e_s = 5000.0;
  p.prnu_fraction = 0.05;
  const DetectorPattern a = build_detector_pattern(p, kPixels), b = build_detector_pattern(p, kPixels);
  EXPECT_EQ(a.response, b.response);
  EXPECT_EQ(a.dark_current_e_s, b.dark_current_e_s);
  double hot = 0, dead = 0, sum = 0, sum2 = 0;
  for (std::int64_t i = 0; i < kPixels; ++i) {
    hot += a.dark_current_e_s[i] == 5000.0;
    dead += a.response[i] == 0.0;
    if (a.response[i] > 0) sum += a.response[i], sum2 += a.response[i] * a.response[i];
  }
  const double n = static_cast<double>(kPixels);
  EXPECT_NEAR(hot / n, 0.002, 5 * std::sqrt(0.002 / n));
  EXPECT_NEAR(dead / n, 0.001, 5 * std::sqrt(0.001 / n));
  const double live = n - dead, mean = sum / live;
  EXPECT_NEAR(std::sqrt(sum2 / live - mean * mean), 0.05, 0.05 * 0.01);  // PRNU sigma, 1 % (0.2 % standard error)
  p.pattern_seed = 2;
  EXPECT_NE(build_detector_pattern(p, kPixels).response, a.response);
  // Dead pixels give no photo-electrons: with noise off, their charge is the dark signal alone.
  std::mt19937_64 rng(1);
  std::vector<double> electrons;
  std::vector<std::uint32_t> adu;
  apply_detector(p, a, std::vector<double>(kPixels, 1000.0), 1.0, false, rng, electrons, adu);
  for (std::int64_t i = 0; i < kPixels; ++i)
    if (a.response[i] == 0.0) {
      ASSERT_EQ(electrons[i], a.dark_current_e_s[i]);
    }
}

// Noise off: the stage is its means, the ADU the rounding of e / g + bias.
TEST(Detector, WithoutNoiseTheStageIsItsMean) {
  DetectorParameters p;
  p.enabled = true;
  p.gain_e_per_adu = 4.0;
  p.bias_adu = 200.0;
  p.dark_current_e_s = 10.0;
  const DetectorPattern pattern = build_detector_pattern(p, 4);
  std::mt19937_64 rng(1);
  const std::mt19937_64 before = rng;
  std::vector<double> electrons;
  std::vector<std::uint32_t> adu;
  apply_detector(p, pattern, {0.0, 10.0, 1001.0, std::nan("")}, 0.5, false, rng, electrons, adu);
  EXPECT_EQ(rng, before);  // no draw
  EXPECT_EQ(electrons, (std::vector<double>{5.0, 15.0, 1006.0, 5.0}));
  // floor(5 / 4 + 200.5) = 201, floor(15 / 4 + 200.5) = 204, floor(1006 / 4 + 200.5) = 452.
  EXPECT_EQ(adu, (std::vector<std::uint32_t>{201, 204, 452, 201}));
}

}  // namespace
