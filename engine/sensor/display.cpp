#include "sensor/display.hpp"

#include <algorithm>
#include <cmath>
#include <thread>
#include <utility>

#include "core/parallel_ranges.hpp"

namespace eoir::sensor {
namespace {

constexpr std::int64_t kChunk = 4096;  // values made at a time, per thread

// The stretches' constants (display.hpp) and zscale's (IRAF; astropy's
// ZScaleInterval defaults).
constexpr double kLogA = 1000.0;
constexpr double kAsinhB = 0.1;
constexpr std::int64_t kZscaleSamples = 1000;
constexpr std::int64_t kZscaleMinPixels = 5;
constexpr double kZscaleMaxReject = 0.5;
constexpr double kZscaleContrast = 0.25;
constexpr double kZscaleRejectSigma = 2.5;
constexpr int kZscaleIterations = 5;

// zscale's limits of the samples (sorted here).
void zscale_of_samples(std::vector<double>& s, double& lo, double& hi) {
  const std::int64_t n = static_cast<std::int64_t>(s.size());
  if (n == 0) {
    lo = hi = 0.0;
    return;
  }
  std::sort(s.begin(), s.end());
  lo = s.front();
  hi = s.back();
  // A line fitted to the sorted samples with k-sigma rejection of outliers,
  // the rejected set grown by 1 % of the samples each round.
  const std::int64_t min_good =
      std::max(kZscaleMinPixels, static_cast<std::int64_t>(static_cast<double>(n) * kZscaleMaxReject));
  const std::int64_t grow = std::max<std::int64_t>(1, static_cast<std::int64_t>(static_cast<double>(n) * 0.01));
  const std::int64_t reach = (grow - 1) / 2;  // a rejected sample j rejects [j - reach, j + grow - 1 - reach]
  std::vector<char> bad(static_cast<std::size_t>(n), 0), grown(static_cast<std::size_t>(n), 0);
  std::int64_t good = n, last_good = n + 1;
  double slope = 0.0;
  for (int iteration = 0; iteration < kZscaleIterations; ++iteration) {
    if (good >= last_good || good < min_good) break;
    double m = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::int64_t i = 0; i < n; ++i) {
      if (bad[static_cast<std::size_t>(i)]) continue;
      const double x = static_cast<double>(i), y = s[static_cast<std::size_t>(i)];
      m += 1;
      sx += x;
      sy += y;
      sxx += x * x;
      sxy += x * y;
    }
    const double det = m * sxx - sx * sx;
    slope = det != 0.0 ? (m * sxy - sx * sy) / det : 0.0;
    const double intercept = (sy - slope * sx) / m;
    double mean = 0, var = 0;
    for (std::int64_t i = 0; i < n; ++i)
      if (!bad[static_cast<std::size_t>(i)])
        mean += s[static_cast<std::size_t>(i)] - (slope * static_cast<double>(i) + intercept);
    mean /= m;
    for (std::int64_t i = 0; i < n; ++i)
      if (!bad[static_cast<std::size_t>(i)]) {
        const double d = s[static_cast<std::size_t>(i)] - (slope * static_cast<double>(i) + intercept) - mean;
        var += d * d;
      }
    const double threshold = kZscaleRejectSigma * std::sqrt(var / m);
    for (std::int64_t i = 0; i < n; ++i) {
      const double flat = s[static_cast<std::size_t>(i)] - (slope * static_cast<double>(i) + intercept);
      if (flat < -threshold || flat > threshold) bad[static_cast<std::size_t>(i)] = 1;
    }
    std::fill(grown.begin(), grown.end(), 0);
    for (std::int64_t j = 0; j < n; ++j)
      if (bad[static_cast<std::size_t>(j)])
        for (std::int64_t i = std::max<std::int64_t>(0, j - reach); i <= std::min(n - 1, j + grow - 1 - reach); ++i)
          grown[static_cast<std::size_t>(i)] = 1;
    bad.swap(grown);
    last_good = good;
    good = std::count(bad.begin(), bad.end(), 0);
  }
  if (good < min_good) return;  // too much rejected: the extremes
  slope /= kZscaleContrast;
  const std::int64_t centre = (n - 1) / 2;
  const double median = n % 2 ? s[static_cast<std::size_t>(n / 2)]
                              : 0.5 * (s[static_cast<std::size_t>(n / 2 - 1)] + s[static_cast<std::size_t>(n / 2)]);
  lo = std::max(lo, median - static_cast<double>(centre - 1) * slope);
  hi = std::min(hi, median + static_cast<double>(n - centre) * slope);
}

// zscale's samples: every stride-th value (stride = n / 1000, at least 1),
// the first 1000 of them, non-finite values skipped.
template <class Fill>
void zscale_of(std::int64_t n, const Fill& fill, double& lo, double& hi) {
  const std::int64_t stride =
      std::max<std::int64_t>(1, static_cast<std::int64_t>(static_cast<double>(n) / static_cast<double>(kZscaleSamples)));
  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(kZscaleSamples));
  for (std::int64_t i = 0; i < n && static_cast<std::int64_t>(samples.size()) < kZscaleSamples; i += stride) {
    double v = 0;
    fill(i, i + 1, &v);
    if (std::isfinite(v)) samples.push_back(v);
  }
  zscale_of_samples(samples, lo, hi);
}

// Compresses n values to bytes (display.hpp). fill(begin, end, out) writes
// values [begin, end) to out: they are made twice (for the range, then for
// the bytes) in chunks, never held whole.
template <class Fill>
std::vector<std::uint8_t> compress(std::int64_t n, const Fill& fill, const DisplayOptions& o, unsigned threads,
                                   std::vector<std::uint8_t> out) {
  out.resize(static_cast<std::size_t>(n));  // every byte is written below
  if (n == 0) return out;
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  double lo = 0, hi = 0;
  if (o.stretch == DisplayStretch::zscale) {
    zscale_of(n, fill, lo, hi);
  } else if (o.agc) {
    // Least and greatest value, per range then together.
    std::vector<std::pair<double, double>> ranges(parallel_range_count(n, threads), {INFINITY, -INFINITY});
    parallel_indexed_ranges(n, threads, [&](unsigned t, std::int64_t b, std::int64_t e) {
      double values[kChunk], mn = INFINITY, mx = -INFINITY;
      for (std::int64_t i = b; i < e; i += kChunk) {
        const std::int64_t m = std::min(kChunk, e - i);
        fill(i, i + m, values);
        const auto [lo_it, hi_it] = std::minmax_element(values, values + m);
        mn = std::min(mn, *lo_it);
        mx = std::max(mx, *hi_it);
      }
      ranges[t] = {mn, mx};
    });
    lo = INFINITY;
    hi = -INFINITY;
    for (const auto& r : ranges) {
      lo = std::min(lo, r.first);
      hi = std::max(hi, r.second);
    }
  } else {
    hi = o.full_scale / std::pow(30.0, static_cast<double>(o.gain_step));
  }
  // scale: bytes per unit value, linear. A flat range shows mid-grey rather
  // than dividing by zero (the "strange effects" of AGC on low-contrast
  // scenes, spec 4.1.2), black if it is zero.
  const bool flat = !(hi > lo);
  const double scale = o.agc || o.stretch == DisplayStretch::zscale
                           ? 255.0 / (hi - lo)
                           : 255.0 * std::pow(30.0, static_cast<double>(o.gain_step)) / o.full_scale;
  const std::uint8_t flat_byte = hi > 0 ? 128 : 0;
  const double log_norm = std::log1p(kLogA), asinh_norm = std::asinh(1.0 / kAsinhB);
  const auto byte_of = [&](double v) -> std::uint8_t {
    if (v >= o.saturation) return 255;
    if (flat) return flat_byte;
    const double linear = std::clamp((v - lo) * scale, 0.0, 255.0);  // NaN stays NaN: 0 below
    double y = 0;
    switch (o.stretch) {
      case DisplayStretch::linear:
      case DisplayStretch::zscale: y = linear; break;
      case DisplayStretch::log: y = 255.0 * std::log1p(kLogA * linear / 255.0) / log_norm; break;
      case DisplayStretch::asinh: y = 255.0 * std::asinh(linear / 255.0 / kAsinhB) / asinh_norm; break;
    }
    return std::isfinite(y) ? static_cast<std::uint8_t>(std::clamp(std::round(y), 0.0, 255.0)) : 0;
  };
  parallel_ranges(n, threads, [&](std::int64_t b, std::int64_t e) {
    double values[kChunk];
    for (std::int64_t i = b; i < e; i += kChunk) {
      const std::int64_t m = std::min(kChunk, e - i);
      fill(i, i + m, values);
      for (std::int64_t j = 0; j < m; ++j) out[static_cast<std::size_t>(i + j)] = byte_of(values[j]);
    }
  });
  return out;
}

}  // namespace

void zscale_limits(const std::vector<double>& values, double& lo, double& hi) {
  const auto fill = [&values](std::int64_t b, std::int64_t e, double* out) {
    std::copy(values.begin() + b, values.begin() + e, out);
  };
  zscale_of(static_cast<std::int64_t>(values.size()), fill, lo, hi);
}

std::vector<std::uint8_t> compress_for_display(const std::vector<double>& values, const DisplayOptions& options,
                                               unsigned threads, std::vector<std::uint8_t> storage) {
  const auto fill = [&values](std::int64_t b, std::int64_t e, double* out) {
    std::copy(values.begin() + b, values.begin() + e, out);
  };
  return compress(static_cast<std::int64_t>(values.size()), fill, options, threads, std::move(storage));
}

std::vector<std::uint8_t> scene_display(const radiometry::RadianceImage& scene, const DisplayOptions& options,
                                        unsigned threads, std::vector<std::uint8_t> storage) {
  const geometry::SampleGrid& g = scene.grid;
  const std::int64_t w = g.width(), fw = g.field_width(), fh = g.field_height(), guard = g.guard_samples();
  // dOmega = dA' cos^3(theta) / f^2 (SampleGrid::sample_solid_angle_sr) with
  // the tangents of each column and row computed once.
  std::vector<double> tx(static_cast<std::size_t>(fw)), ty(static_cast<std::size_t>(fh));
  for (std::int64_t c = 0; c < fw; ++c) tx[static_cast<std::size_t>(c)] = g.tan_x(c + guard);
  for (std::int64_t r = 0; r < fh; ++r) ty[static_cast<std::size_t>(r)] = g.tan_y(r + guard);
  const double k = static_cast<double>(g.per_pixel);
  const double d_area = (g.pitch_x_cm / k) * (g.pitch_y_cm / k);
  const double f2 = g.focal_length_cm * g.focal_length_cm;
  // Point sources go to their nearest sample, in scene order within a sample.
  std::vector<std::pair<std::int64_t, double>> point_irradiance;
  point_irradiance.reserve(scene.point_sources.size());
  for (const radiometry::PointSource& ps : scene.point_sources) {
    const std::int64_t c = std::clamp<std::int64_t>(std::lround(ps.column) - guard, 0, fw - 1);
    const std::int64_t r = std::clamp<std::int64_t>(std::lround(ps.row) - guard, 0, fh - 1);
    point_irradiance.emplace_back(r * fw + c, ps.irradiance_W_cm2);
  }
  std::stable_sort(point_irradiance.begin(), point_irradiance.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  const auto fill = [&](std::int64_t b, std::int64_t e, double* out) {
    for (std::int64_t i = b; i < e;) {  // row by row
      const std::int64_t r = i / fw, c0 = i % fw, n = std::min(fw - c0, e - i);
      const double u = ty[static_cast<std::size_t>(r)];
      const double* radiance = scene.radiance_W_cm2_sr.data() + (r + guard) * w + guard + c0;
      const double* t = tx.data() + c0;
      double* o = out + (i - b);
      for (std::int64_t j = 0; j < n; ++j) {
        const double cos_theta = 1.0 / std::sqrt(1.0 + t[j] * t[j] + u * u);
        o[j] = radiance[j] * (d_area * cos_theta * cos_theta * cos_theta / f2);
      }
      i += n;
    }
    auto it = std::lower_bound(point_irradiance.begin(), point_irradiance.end(), b,
                               [](const auto& p, std::int64_t i) { return p.first < i; });
    for (; it != point_irradiance.end() && it->first < e; ++it) out[it->first - b] += it->second;
  };
  DisplayOptions o = options;
  o.full_scale = 1e-6;
  o.saturation = HUGE_VAL;
  return compress(fw * fh, fill, o, threads, std::move(storage));
}

}  // namespace eoir::sensor
