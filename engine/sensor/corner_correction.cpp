#include "sensor/corner_correction.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <utility>

#include "core/constants.hpp"
#include "sensor/catmull_rom.hpp"
#include "sensor/sensor_model.hpp"

namespace eoir::sensor {
namespace {

constexpr double kNearLambdaF = 16.0;          // the grid's reach for a diffraction-limited PSF
constexpr double kNearJitterSigmas = 8.0;      // plus this many jitter sigmas
constexpr double kNearBlurDiameters = 2.0;     // and defocus blur diameters
constexpr std::int64_t kMinQuadrature = 256;   // midpoint nodes per axis on [0, 1] (error ~4e-5)
constexpr double kQuadraturePerLambdaF = 10.0;  // and at least this many per lambda F# of reach (5e-5 at 8)
constexpr std::int64_t kTailQuadrature = 2048;  // for T (error ~1e-7)
constexpr std::size_t kKept = 8;                // optics kept process-wide

// The optics in lambda F# units: what the normalised OTF depends on.
struct Key {
  double wavefront_error_rms_waves, jitter_lf, defocus_lf;
  std::int64_t otf_table_size;
  bool operator==(const Key& o) const {
    return wavefront_error_rms_waves == o.wavefront_error_rms_waves && jitter_lf == o.jitter_lf &&
           defocus_lf == o.defocus_lf && otf_table_size == o.otf_table_size;
  }
};

CornerCorrection build(const OpticsModel& optics, std::int64_t otf_table_size) {
  const auto t0 = std::chrono::steady_clock::now();
  CornerCorrection c;
  const double lambda_f_cm = optics.diffraction_wavelength_cm * optics.f_number;
  const double cutoff = optics.cutoff_cycles_per_cm();
  // The radial OTF against nu = frequency / cutoff, tabulated and
  // interpolated linearly as the PSF folds do (system_psf.cpp).
  std::vector<double> table(static_cast<std::size_t>(otf_table_size + 2), 0.0);
  for (std::int64_t k = 0; k <= otf_table_size; ++k)
    table[static_cast<std::size_t>(k)] = optics.system(cutoff * static_cast<double>(k) / static_cast<double>(otf_table_size));
  const auto scale = static_cast<double>(otf_table_size);
  auto otf = [&](double nu) {
    if (nu >= 1.0) return 0.0;
    const double u = nu * scale;
    const auto k = static_cast<std::size_t>(u);
    const double f = u - static_cast<double>(k);
    return table[k] + f * (table[k + 1] - table[k]);
  };
  // A = s / (4 pi^2): the 2-D transform of -s |nu| is s / (4 pi^2 r^3).
  c.tail_coefficient = (table[0] - table[1]) * scale / (4.0 * constants::pi * constants::pi);

  const PsfReach reach{kNearLambdaF, kNearJitterSigmas, kNearBlurDiameters};
  c.near_lf = psf_reach_cm(optics, reach) / lambda_f_cm;
  const double h = c.step_lf;
  c.nodes = static_cast<std::int64_t>(std::ceil(c.near_lf / h)) + 3;
  const std::int64_t m = c.nodes;

  // T(x) = 1/2 - (1 / pi) int_0^1 OTF(u) sin(2 pi u x) / u du.
  {
    const std::int64_t n = kTailQuadrature;
    std::vector<double> weight(static_cast<std::size_t>(n)), freq(static_cast<std::size_t>(n));
    for (std::int64_t a = 0; a < n; ++a) {
      const double u = (static_cast<double>(a) + 0.5) / static_cast<double>(n);
      freq[static_cast<std::size_t>(a)] = 2.0 * constants::pi * u;
      weight[static_cast<std::size_t>(a)] = otf(u) / u / (constants::pi * static_cast<double>(n));
    }
    const auto count = static_cast<std::int64_t>(std::ceil((c.near_lf + 1.0) / c.tail_step_lf)) + 3;
    c.tail.assign(static_cast<std::size_t>(count), 0.5);
    // sin(k theta) by the recurrence s_k+1 = 2 cos(theta) s_k - s_k-1.
    for (std::int64_t a = 0; a < n; ++a) {
      const double theta = freq[static_cast<std::size_t>(a)] * c.tail_step_lf, twice_cos = 2.0 * std::cos(theta);
      const double w = weight[static_cast<std::size_t>(a)];
      double previous = 0.0, current = std::sin(theta);
      for (std::int64_t k = 1; k < count; ++k) {
        c.tail[static_cast<std::size_t>(k)] -= w * current;
        const double next = twice_cos * current - previous;
        previous = current;
        current = next;
      }
    }
  }

  // G on the grid: S F S^T with F(u, v) = D(u, v) / (u v pi^2 n^2), S(i, a) = sin(2 pi u_a x_i).
  const std::int64_t n =
      std::max(kMinQuadrature, static_cast<std::int64_t>(std::ceil(kQuadraturePerLambdaF * c.near_lf)));
  std::vector<double> u(static_cast<std::size_t>(n)), otf_u(static_cast<std::size_t>(n));
  for (std::int64_t a = 0; a < n; ++a) {
    u[static_cast<std::size_t>(a)] = (static_cast<double>(a) + 0.5) / static_cast<double>(n);
    otf_u[static_cast<std::size_t>(a)] = otf(u[static_cast<std::size_t>(a)]);
  }
  const double norm = 1.0 / (constants::pi * constants::pi * static_cast<double>(n) * static_cast<double>(n));
  std::vector<double> f(static_cast<std::size_t>(n * n));
  for (std::int64_t a = 0; a < n; ++a)
    for (std::int64_t b = 0; b <= a; ++b) {
      const double ua = u[static_cast<std::size_t>(a)], ub = u[static_cast<std::size_t>(b)];
      const double d = otf(std::sqrt(ua * ua + ub * ub)) - otf_u[static_cast<std::size_t>(a)] * otf_u[static_cast<std::size_t>(b)];
      f[static_cast<std::size_t>(a * n + b)] = f[static_cast<std::size_t>(b * n + a)] = d / (ua * ub) * norm;
    }
  std::vector<double> s(static_cast<std::size_t>(m * n));
  for (std::int64_t i = 0; i < m; ++i)
    for (std::int64_t a = 0; a < n; ++a)
      s[static_cast<std::size_t>(i * n + a)] =
          std::sin(2.0 * constants::pi * u[static_cast<std::size_t>(a)] * static_cast<double>(i) * h);
  // P(a, j) = sum_b F(b, a) S(j, b) (F is symmetric); G(i, j) = sum_a S(i, a)
  // P(a, j). Both as sums of rows, which vectorise without reassociation.
  std::vector<double> p(static_cast<std::size_t>(n * m), 0.0);
  {
    std::vector<double> row(static_cast<std::size_t>(n));
    for (std::int64_t j = 0; j < m; ++j) {
      std::fill(row.begin(), row.end(), 0.0);
      for (std::int64_t b = 0; b < n; ++b) {
        const double sjb = s[static_cast<std::size_t>(j * n + b)];
        const double* fb = &f[static_cast<std::size_t>(b * n)];
        for (std::int64_t a = 0; a < n; ++a) row[static_cast<std::size_t>(a)] += sjb * fb[a];
      }
      for (std::int64_t a = 0; a < n; ++a) p[static_cast<std::size_t>(a * m + j)] = row[static_cast<std::size_t>(a)];
    }
  }
  c.g.assign(static_cast<std::size_t>(m * m), 0.0);
  for (std::int64_t i = 0; i < m; ++i) {
    double* gi = &c.g[static_cast<std::size_t>(i * m)];
    for (std::int64_t a = 0; a < n; ++a) {
      const double sia = s[static_cast<std::size_t>(i * n + a)];
      const double* pa = &p[static_cast<std::size_t>(a * m)];
      for (std::int64_t j = 0; j < m; ++j) gi[j] += sia * pa[j];
    }
  }
  c.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return c;
}

}  // namespace

double CornerCorrection::beyond(double x_lf) const {
  const double t = x_lf / tail_step_lf;
  const auto last = static_cast<double>(tail.size()) - 3.0;
  if (t >= last) return 2.0 * tail_coefficient / x_lf;  // the A / r^3 tail: LSF 2 A / x^2
  const auto k = static_cast<std::int64_t>(t);
  double w[4];
  catmull_rom_weights(t - static_cast<double>(k), w);
  double v = 0;
  for (int q = 0; q < 4; ++q) {
    const std::int64_t node = k - 1 + q;
    v += w[q] * (node < 0 ? 1.0 - tail[static_cast<std::size_t>(-node)] : tail[static_cast<std::size_t>(node)]);
  }
  return v;
}

double CornerCorrection::at(double x_lf, double y_lf) const {
  const double sign = (x_lf < 0) == (y_lf < 0) ? 1.0 : -1.0;
  const double x = std::abs(x_lf), y = std::abs(y_lf);
  if (x > near_lf || y > near_lf) {
    const double r = std::sqrt(x * x + y * y);
    return sign * (2.0 * tail_coefficient / (x + y + r) - beyond(x) * beyond(y));
  }
  const double tx = x / step_lf, ty = y / step_lf;
  const auto i = static_cast<std::int64_t>(tx), j = static_cast<std::int64_t>(ty);
  double wx[4], wy[4];
  catmull_rom_weights(tx - static_cast<double>(i), wx);
  catmull_rom_weights(ty - static_cast<double>(j), wy);
  double v = 0;
  for (int a = 0; a < 4; ++a) {
    const std::int64_t ni = i - 1 + a;  // G is odd: G(-h, y) = -G(h, y)
    const double si = ni < 0 ? -1.0 : 1.0;
    const double* row = &g[static_cast<std::size_t>(std::abs(ni) * nodes)];
    double r = 0;
    for (int b = 0; b < 4; ++b) {
      const std::int64_t nj = j - 1 + b;
      r += wy[b] * (nj < 0 ? -row[-nj] : row[nj]);
    }
    v += wx[a] * si * r;
  }
  return sign * v;
}

std::shared_ptr<const CornerCorrection> corner_correction(const OpticsModel& optics, std::int64_t otf_table_size) {
  const double lambda_f_cm = optics.diffraction_wavelength_cm * optics.f_number;
  const Key key{optics.wavefront_error_rms_waves, optics.jitter_mrad * 1e-3 * optics.focal_length_cm / lambda_f_cm,
                optics.defocus_cm / (optics.f_number * lambda_f_cm), otf_table_size};
  static std::mutex mutex;
  static std::vector<std::pair<Key, std::shared_ptr<const CornerCorrection>>> kept;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (const auto& [k, c] : kept)
      if (k == key) return c;
  }
  // Built from the optics scaled to lambda F# = 1 cm (F# 1, f 1000 cm: the
  // jitter in mrad is then its sigma in lambda F#): the same table for every
  // optics with this key.
  OpticsModel normalised;
  normalised.focal_length_cm = 1000.0;
  normalised.f_number = 1.0;
  normalised.diffraction_wavelength_cm = 1.0;
  normalised.wavefront_error_rms_waves = key.wavefront_error_rms_waves;
  normalised.jitter_mrad = key.jitter_lf;
  normalised.defocus_cm = key.defocus_lf;
  auto built = std::make_shared<const CornerCorrection>(build(normalised, otf_table_size));
  const std::lock_guard<std::mutex> lock(mutex);
  for (const auto& [k, c] : kept)
    if (k == key) return c;
  if (kept.size() == kKept) kept.erase(kept.begin());
  kept.emplace_back(key, built);
  return built;
}

}  // namespace eoir::sensor
