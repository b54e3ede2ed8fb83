#include "sensor/display.hpp"

#include <algorithm>
#include <cmath>
#include <thread>
#include <utility>

#include "core/parallel_ranges.hpp"

namespace eoir::sensor {
namespace {

constexpr std::int64_t kChunk = 4096;  // values made at a time, per thread

// Compresses n values to bytes (spec 4.1.2). fill(begin, end, out) writes
// values [begin, end) to out: they are made twice (for the AGC's least and
// greatest value, then for the bytes) in chunks, never held whole.
template <class Fill>
std::vector<std::uint8_t> compress(std::int64_t n, const Fill& fill, bool agc, std::int64_t gain_step,
                                   double full_scale, unsigned threads, std::vector<std::uint8_t> out) {
  out.resize(static_cast<std::size_t>(n));  // every byte is written below
  if (n == 0) return out;
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  double lo = 0, scale = 0;
  if (agc) {
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
    double mn = INFINITY, mx = -INFINITY;
    for (const auto& r : ranges) {
      mn = std::min(mn, r.first);
      mx = std::max(mx, r.second);
    }
    lo = mn;
    // A constant image shows mid-grey rather than dividing by zero (the
    // "strange effects" of AGC on low-contrast scenes, spec 4.1.2).
    scale = mx > mn ? 255.0 / (mx - mn) : 0.0;
    if (scale == 0.0) {
      std::fill(out.begin(), out.end(), static_cast<std::uint8_t>(mx > 0 ? 128 : 0));
      return out;
    }
  } else {
    scale = 255.0 * std::pow(30.0, static_cast<double>(gain_step)) / full_scale;
  }
  parallel_ranges(n, threads, [&](std::int64_t b, std::int64_t e) {
    double values[kChunk];
    for (std::int64_t i = b; i < e; i += kChunk) {
      const std::int64_t m = std::min(kChunk, e - i);
      fill(i, i + m, values);
      for (std::int64_t j = 0; j < m; ++j)
        out[static_cast<std::size_t>(i + j)] =
            static_cast<std::uint8_t>(std::clamp(std::round((values[j] - lo) * scale), 0.0, 255.0));
    }
  });
  return out;
}

}  // namespace

std::vector<std::uint8_t> compress_for_display(const std::vector<double>& values, bool agc, std::int64_t gain_step,
                                               double full_scale, unsigned threads,
                                               std::vector<std::uint8_t> storage) {
  const auto fill = [&values](std::int64_t b, std::int64_t e, double* out) {
    std::copy(values.begin() + b, values.begin() + e, out);
  };
  return compress(static_cast<std::int64_t>(values.size()), fill, agc, gain_step, full_scale, threads,
                  std::move(storage));
}

std::vector<std::uint8_t> scene_display(const radiometry::RadianceImage& scene, bool agc, std::int64_t gain_step,
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
  return compress(fw * fh, fill, agc, gain_step, 1e-6, threads, std::move(storage));
}

}  // namespace eoir::sensor
