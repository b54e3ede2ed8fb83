#include "sensor/display.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <utility>

#include "core/parallel_ranges.hpp"

namespace eoir::sensor {

std::vector<std::uint8_t> compress_for_display(const std::vector<double>& values, bool agc, std::int64_t gain_step,
                                               double full_scale, unsigned threads) {
  std::vector<std::uint8_t> out(values.size(), 0);
  if (values.empty()) return out;
  const auto n = static_cast<std::int64_t>(values.size());
  double lo = 0, scale = 0;
  if (agc) {
    // Least and greatest value, per range then together.
    std::vector<std::pair<double, double>> ranges(std::max(1u, threads == 0 ? std::thread::hardware_concurrency() : threads),
                                                  {values[0], values[0]});
    std::atomic<std::size_t> next{0};
    parallel_ranges(n, static_cast<unsigned>(ranges.size()), [&](std::int64_t b, std::int64_t e) {
      const auto [mn, mx] = std::minmax_element(values.begin() + b, values.begin() + e);
      ranges[next++] = {*mn, *mx};
    });
    double mn = values[0], mx = values[0];
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
    for (std::int64_t i = b; i < e; ++i) {
      const double v = std::round((values[static_cast<std::size_t>(i)] - lo) * scale);
      out[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0));
    }
  });
  return out;
}

}  // namespace eoir::sensor

namespace eoir::sensor {

std::vector<std::uint8_t> scene_display(const radiometry::RadianceImage& scene, bool agc, std::int64_t gain_step,
                                        unsigned threads) {
  const geometry::SampleGrid& g = scene.grid;
  const std::int64_t w = g.width(), fw = g.field_width(), fh = g.field_height(), guard = g.guard_samples();
  std::vector<double> irradiance(static_cast<std::size_t>(fw * fh));
  // dOmega = dA' cos^3(theta) / f^2 (SampleGrid::sample_solid_angle_sr) with
  // the tangents of each column and row computed once.
  std::vector<double> tx(static_cast<std::size_t>(fw)), ty(static_cast<std::size_t>(fh));
  for (std::int64_t c = 0; c < fw; ++c) tx[static_cast<std::size_t>(c)] = g.tan_x(c + guard);
  for (std::int64_t r = 0; r < fh; ++r) ty[static_cast<std::size_t>(r)] = g.tan_y(r + guard);
  const double k = static_cast<double>(g.per_pixel);
  const double d_area = (g.pitch_x_cm / k) * (g.pitch_y_cm / k);
  const double f2 = g.focal_length_cm * g.focal_length_cm;
  parallel_ranges(fh, threads, [&](std::int64_t r0, std::int64_t r1) {
    for (std::int64_t r = r0; r < r1; ++r) {
      const double ty2 = ty[static_cast<std::size_t>(r)] * ty[static_cast<std::size_t>(r)];
      const double* radiance = scene.radiance_W_cm2_sr.data() + (r + guard) * w + guard;
      double* out = irradiance.data() + r * fw;
      for (std::int64_t c = 0; c < fw; ++c) {
        const double t = tx[static_cast<std::size_t>(c)];
        const double cos_theta = 1.0 / std::sqrt(1.0 + t * t + ty2);
        out[c] = radiance[c] * (d_area * cos_theta * cos_theta * cos_theta / f2);
      }
    }
  }, 16);
  for (const radiometry::PointSource& ps : scene.point_sources) {
    const std::int64_t c = std::clamp<std::int64_t>(std::lround(ps.column) - guard, 0, fw - 1);
    const std::int64_t r = std::clamp<std::int64_t>(std::lround(ps.row) - guard, 0, fh - 1);
    irradiance[static_cast<std::size_t>(r * fw + c)] += ps.irradiance_W_cm2;
  }
  return compress_for_display(irradiance, agc, gain_step, 1e-6, threads);
}

}  // namespace eoir::sensor
