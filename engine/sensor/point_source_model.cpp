#include "sensor/point_source_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/fftw_plans.hpp"
#include "sensor/sensor_model.hpp"
#include "sensor/system_psf.hpp"

namespace eoir::sensor {
namespace {

constexpr std::int64_t kMaxTableFft = 2048;  // FFT size cap of the table builds (64 MB of transient buffers)
// FFT period of a table: at least twice its extent, and far enough that the
// PSF's copies alias below 1e-6 of the energy into any pixel: eight copies
// of E(r) ~ (lambda F# / p) / (pi^3 r^3) per pixel at r = P pixels (the
// Airy tail) give P = (8e6 / pi^3)^(1/3) (lambda F# / p)^(1/3) = 64 (lambda F# / p)^(1/3).
constexpr double kTablePeriodPerExtent = 2.0;
constexpr double kAliasPeriodPixels = 64.0;

// Pixels wider than point_quadrant_lambda_f (16 lambda F# by default, along
// either axis) take E(u) as the product of the pixel-integrated line-spread
// functions along x and y (pixel_integrated_lsf) plus the corner terms of G
// (corner_correction.hpp): the inclusion-exclusion of the PSF's quadrant
// energies, exact up to G's table (about 1e-4 of the energy per pixel). The
// 2-D FFT path's OTF fold costs pi (period / lambda F#)^2 evaluations per
// table; a window of 500 lambda F# needs some 1e6 to 1e7 (0.2 s at 18
// lambda F#, seconds at 140, minutes at 1e4: a 64-pixel camera of 120 deg),
// the 1-D path milliseconds (G's table, a few ms, is kept per optics).
// With point_wide_pixels product: the plain product from 32 lambda F# (off
// by up to 1.4 % of the energy for a source near a pixel corner, where G
// peaks), the 2-D FFT tables below.
constexpr double kPlainProductPixelLambdaF = 32.0;
// The line-spread function falls only as 2 A / x^2 (A = pi^-3, x in lambda
// F#), so its FFT period P must be long: the copies put about 8 A W / P^2
// of the energy into a window of half-width W (8e-6 for W = 513 lambda F#,
// the 500 lambda F# window, at this P). A 1-D FFT of P / (lambda F# / 4)
// points costs well under a millisecond.
constexpr double kLsfPeriodLambdaF = 4096.0;

bool quadrant(const Fidelity& f) { return f.point_wide_pixels == WidePixelTables::quadrant; }

}  // namespace

bool separable_pixels(const OpticsModel& optics, const geometry::SampleGrid& g, const Fidelity& f) {
  return std::max(g.pitch_x_cm, g.pitch_y_cm) / (optics.diffraction_wavelength_cm * optics.f_number) >
         (quadrant(f) ? f.point_quadrant_lambda_f : kPlainProductPixelLambdaF);
}

namespace {

// E(u) at u = (j + delta) / steps pixels along each axis, j in [-half,
// half] (at least), delta = 1/2 for odd `steps` (so that the table offsets
// -1/2 + i / steps fall on samples): element (j_x, j_y) of the result. One
// FFT of at most kMaxTableFft points when its period at this step is long
// enough; otherwise m x m FFTs at m steps, interleaved (j = m i + r, r in
// [0, m)). `otf`: the radial OTF table (radial_otf_table).
FocalPlaneSamples pixel_energy_samples(const OpticsModel& optics, const geometry::SampleGrid& g, std::int64_t steps,
                                       std::int64_t half, const Fidelity& f, const std::vector<double>& otf) {
  const double delta = steps % 2 ? 0.5 : 0.0;
  const double lambda_f_cm = optics.diffraction_wavelength_cm * optics.f_number;
  const double pixel_in_lambda_f = std::max(g.pitch_x_cm, g.pitch_y_cm) / lambda_f_cm;
  const double extent_px = 2.0 * static_cast<double>(half) / static_cast<double>(steps);
  const double period_px =
      std::max(kTablePeriodPerExtent * extent_px, kAliasPeriodPixels / std::cbrt(pixel_in_lambda_f));
  const double fine_x = g.pitch_x_cm / static_cast<double>(steps), fine_y = g.pitch_y_cm / static_cast<double>(steps);
  FocalPlaneSamples e;
  e.size = 2 * half + 1;
  e.step_x_cm = fine_x;
  e.step_y_cm = fine_y;
  if (separable_pixels(optics, g, f)) {
    const double lsf_period_px =
        quadrant(f) ? std::max(period_px, kLsfPeriodLambdaF / pixel_in_lambda_f) : period_px;
    const std::vector<double> ex =
        pixel_integrated_lsf(optics, g.pitch_x_cm, fine_x, half, delta * fine_x, lsf_period_px * g.pitch_x_cm, otf);
    const std::vector<double> ey =
        g.pitch_y_cm == g.pitch_x_cm
            ? ex
            : pixel_integrated_lsf(optics, g.pitch_y_cm, fine_y, half, delta * fine_y, lsf_period_px * g.pitch_y_cm, otf);
    e.values.resize(static_cast<std::size_t>(e.size * e.size));
    for (std::int64_t jy = -half; jy <= half; ++jy)
      for (std::int64_t jx = -half; jx <= half; ++jx)
        e.values[static_cast<std::size_t>((jy + half) * e.size + jx + half)] =
            ex[static_cast<std::size_t>(jx + half)] * ey[static_cast<std::size_t>(jy + half)];
    return e;
  }
  const auto period_fine = static_cast<std::int64_t>(std::ceil(period_px * static_cast<double>(steps)));
  const std::int64_t m = (period_fine + kMaxTableFft - 1) / kMaxTableFft;
  const std::int64_t coarse_half = half / m + 1, size = 2 * coarse_half + 1;
  const double step_x = fine_x * static_cast<double>(m), step_y = fine_y * static_cast<double>(m);
  // The FFT period, in steps, is the window plus the alias margin
  // (system_psf.cpp): the margin sets it; the FFT is as large as a
  // Nyquist-fine spacing needs at that period, up to the cap (beyond it the
  // spectrum is folded: exact sampling, more OTF evaluations).
  const std::int64_t period_steps =
      std::min(kMaxTableFft, std::max((period_fine + m - 1) / m, size + f.psf_alias_margin_steps));
  PsfNumerics numerics(f);
  numerics.otf_table = &otf;
  numerics.alias_margin_steps = std::max<std::int64_t>(1, period_steps - size);
  const std::int64_t nyquist = std::max(fft_subdivisions(optics, step_x, 1), fft_subdivisions(optics, step_y, 1));
  // point_table_fft_sizes fitted: the smallest even size FFTW transforms
  // quickly (factors 2, 3, 5, 7), not the next power of two (up to 4x the
  // points, for the same period rule).
  const std::int64_t points = std::max<std::int64_t>(128, period_steps * nyquist);
  numerics.fitted_fft_size = f.point_table_fft_sizes == TableFftSizes::fitted;
  if (numerics.fitted_fft_size) {
    numerics.fft_size =
        std::min(kMaxTableFft, 2 * static_cast<std::int64_t>(fftw::good_size(static_cast<int>((points + 1) / 2))));
  } else {
    numerics.fft_size = 128;
    while (numerics.fft_size < kMaxTableFft && numerics.fft_size < points) numerics.fft_size *= 2;
  }
  const auto transform = [&](std::int64_t rx, std::int64_t ry) {
    return pixel_integrated_psf(optics, g.pitch_x_cm, g.pitch_y_cm, step_x, step_y, size,
                                (static_cast<double>(rx) + delta) * fine_x,
                                (static_cast<double>(ry) + delta) * fine_y, numerics);
  };
  if (m == 1) return transform(0, 0);  // (half + 1 samples each side)
  e.values.resize(static_cast<std::size_t>(e.size * e.size));
  for (std::int64_t ry = 0; ry < m; ++ry)
    for (std::int64_t rx = 0; rx < m; ++rx) {
      const FocalPlaneSamples t = transform(rx, ry);
      for (std::int64_t iy = -coarse_half; iy <= coarse_half; ++iy) {
        const std::int64_t jy = m * iy + ry;
        if (jy < -half || jy > half) continue;
        for (std::int64_t ix = -coarse_half; ix <= coarse_half; ++ix) {
          const std::int64_t jx = m * ix + rx;
          if (jx >= -half && jx <= half)
            e.values[static_cast<std::size_t>((jy + half) * e.size + jx + half)] = t.at(ix, iy);
        }
      }
    }
  return e;
}

// The sample j of pixel_energy_samples (or of a line-spread function on
// the same grid) that holds E(d - phi_i) for pixel d at the table's offset
// phi_i = -1/2 + (i - shift) / steps: j = d steps + floor(steps / 2) - (i - shift).
std::int64_t offset_sample(std::int64_t i, std::int64_t d, std::int64_t steps, std::int64_t shift) {
  return d * steps + steps / 2 - (i - shift);
}

// put(i_x, i_y, d_x, d_y, E(d - phi_i)) for offsets i in [0, offsets) and
// pixels |d| <= reach, from pixel_energy_samples.
template <class Put>
void gather(const FocalPlaneSamples& e, std::int64_t steps, std::int64_t offsets, std::int64_t shift,
            std::int64_t reach, Put&& put) {
  const std::int64_t half = e.half();
  const auto sample = [&](std::int64_t i, std::int64_t d) { return offset_sample(i, d, steps, shift) + half; };
  for (std::int64_t iy = 0; iy < offsets; ++iy)
    for (std::int64_t ix = 0; ix < offsets; ++ix)
      for (std::int64_t dy = -reach; dy <= reach; ++dy) {
        const double* row = &e.values[static_cast<std::size_t>(sample(iy, dy) * e.size)];
        for (std::int64_t dx = -reach; dx <= reach; ++dx) put(ix, iy, dx, dy, row[sample(ix, dx)]);
      }
}

// The corner terms of G for the window's pixels |d| <= h at the half-pixel
// offsets phi = -1/2 + i / 2 (i = 0..2 per axis): add(i_x, i_y, d_x, d_y,
// G(X1, Y1) - G(X0, Y1) - G(X1, Y0) + G(X0, Y0)), the pixel spanning
// [d - 1/2 - phi, d + 1/2 - phi] pixels from the source. G is evaluated
// once on the half-pixel grid that holds every such corner.
template <class Add>
void half_pixel_corner_terms(const CornerCorrection& g, double pixel_x_lf, double pixel_y_lf, std::int64_t h,
                             Add&& add) {
  const std::int64_t n = 4 * h + 5;  // corner j <-> (j - 2h - 2) / 2 pixels
  std::vector<double> gc(static_cast<std::size_t>(n * n));
  for (std::int64_t jy = 0; jy < n; ++jy)
    for (std::int64_t jx = 0; jx < n; ++jx)
      gc[static_cast<std::size_t>(jy * n + jx)] = g.at(0.5 * static_cast<double>(jx - 2 * h - 2) * pixel_x_lf,
                                                       0.5 * static_cast<double>(jy - 2 * h - 2) * pixel_y_lf);
  // The corner d + 1/2 - phi_i = d + 1 - i / 2 is j = 2 d + 4 - i + 2 h; d - 1/2 - phi_i is j - 2.
  for (std::int64_t iy = 0; iy < 3; ++iy)
    for (std::int64_t ix = 0; ix < 3; ++ix)
      for (std::int64_t dy = -h; dy <= h; ++dy) {
        const std::int64_t y1 = 2 * dy + 4 - iy + 2 * h, y0 = y1 - 2;
        for (std::int64_t dx = -h; dx <= h; ++dx) {
          const std::int64_t x1 = 2 * dx + 4 - ix + 2 * h, x0 = x1 - 2;
          add(ix, iy, dx, dy,
              gc[static_cast<std::size_t>(y1 * n + x1)] - gc[static_cast<std::size_t>(y1 * n + x0)] -
                  gc[static_cast<std::size_t>(y0 * n + x1)] + gc[static_cast<std::size_t>(y0 * n + x0)]);
        }
      }
}

std::int64_t core_bytes(std::int64_t c, std::int64_t s) { return (2 * c + 1) * (2 * c + 1) * (s + 3) * (s + 3) * 4; }
std::int64_t tail_bytes(std::int64_t h) {
  const std::int64_t s = PointSourceModel::tail_steps + 1;
  return (2 * h + 1) * (2 * h + 1) * s * s * 4;
}

}  // namespace

std::int64_t PointSourceModel::bytes() const {
  std::int64_t total = static_cast<std::int64_t>((core.size() + tail.size()) * sizeof(float) +
                                                 (core_x.size() + core_y.size()) * sizeof(double));
  for (const HaloLevel& l : halo) total += static_cast<std::int64_t>(l.kernel.size() * sizeof(double));
  if (corners) total += corners->bytes();  // shared by the sensors of these optics
  return total;
}

std::int64_t point_window_half(const OpticsModel& optics, const geometry::SampleGrid& g, const Fidelity& f) {
  const auto reach = static_cast<std::int64_t>(
      std::ceil(psf_reach_cm(optics, f.point_psf_reach) / std::min(g.pitch_x_cm, g.pitch_y_cm)));
  return std::clamp<std::int64_t>(
      reach, 2, std::max<std::int64_t>(2, std::min(std::max(g.pixels_x, g.pixels_y), (f.psf_grid_size - 2) / 2)));
}

PointSourceModel build_point_source_model(const OpticsModel& optics, const geometry::SampleGrid& g,
                                          const Fidelity& f) {
  const auto t0 = std::chrono::steady_clock::now();
  PointSourceModel m;
  m.tail_mode = f.point_tail;
  m.window_half = point_window_half(optics, g, f);
  const double min_pitch = std::min(g.pitch_x_cm, g.pitch_y_cm), max_pitch = std::max(g.pitch_x_cm, g.pitch_y_cm);
  const double lambda_f_cm = optics.diffraction_wavelength_cm * optics.f_number;
  const double pixel_in_lambda_f = max_pitch / lambda_f_cm;
  m.taper_start = std::max<std::int64_t>(
      2, static_cast<std::int64_t>(std::ceil(psf_reach_cm(optics, f.point_core_reach) / min_pitch - 1e-9)));
  m.core_steps = std::max<std::int64_t>(
      2, static_cast<std::int64_t>(std::ceil(f.point_offset_steps_per_lambda_f * pixel_in_lambda_f - 1e-9)));
  // Within the memory bound: three quarters of it for the core table, a
  // quarter for the direct tail.
  const double budget = f.point_table_max_mib * 1024.0 * 1024.0;
  auto core_half = [&] {
    return m.window_half <= m.taper_start ? m.window_half : std::min(2 * m.taper_start, m.window_half);
  };
  m.separable = separable_pixels(optics, g, f);
  // The radial OTF table of the line-spread functions or the 2-D folds, made once.
  const std::vector<double> otf = radial_otf_table(optics, f.otf_table_size);
  if (m.separable && quadrant(f)) {
    m.corners = corner_correction(optics, f.otf_table_size);
    m.pixel_x_lf = g.pitch_x_cm / lambda_f_cm;
    m.pixel_y_lf = g.pitch_y_cm / lambda_f_cm;
  }
  auto table_bytes = [&] {  // the 2-D core, or the two 1-D ones of doubles
    const std::int64_t c = core_half(), s = m.core_steps;
    return m.separable ? 2 * (2 * c + 1) * (s + 3) * 8 : core_bytes(c, s);
  };
  while (static_cast<double>(table_bytes()) > 0.75 * budget) {
    if (m.core_steps > 1)
      m.core_steps = std::max<std::int64_t>(1, m.core_steps * 9 / 10);
    else if (m.taper_start > 2)
      m.taper_start = std::max<std::int64_t>(2, m.taper_start / 2);
    else
      break;
  }
  m.core_half = core_half();
  const std::int64_t c = m.core_half, H = m.window_half;

  // Core: offsets i = 0..S + 2 <-> phi = -1/2 + (i - 1) / S; the sample of
  // E(d - phi) is j = d S + floor(S / 2) - (i - 1).
  {
    const std::int64_t s = m.core_steps, offsets = s + 3, half = c * s + s + 1, box = 2 * c + 1;
    if (m.separable) {
      // One line-spread function per axis (the 1-D tables hold S + 3 offsets
      // of 2c + 1 pixels: no memory bound needed).
      const double delta = s % 2 ? 0.5 : 0.0;
      const double period_px = std::max({kTablePeriodPerExtent * 2.0 * static_cast<double>(half) / static_cast<double>(s),
                                         kAliasPeriodPixels / std::cbrt(pixel_in_lambda_f),
                                         quadrant(f) ? kLsfPeriodLambdaF / pixel_in_lambda_f : 0.0});
      auto axis = [&](double pitch_cm, std::vector<double>& table) {
        const double fine = pitch_cm / static_cast<double>(s);
        const std::vector<double> e =
            pixel_integrated_lsf(optics, pitch_cm, fine, half, delta * fine, period_px * pitch_cm, otf);
        table.resize(static_cast<std::size_t>(offsets * box));
        for (std::int64_t i = 0; i < offsets; ++i)
          for (std::int64_t d = -c; d <= c; ++d)
            table[static_cast<std::size_t>(i * box + d + c)] =
                e[static_cast<std::size_t>(offset_sample(i, d, s, 1) + half)];
      };
      axis(g.pitch_x_cm, m.core_x);
      if (g.pitch_y_cm == g.pitch_x_cm)
        m.core_y = m.core_x;
      else
        axis(g.pitch_y_cm, m.core_y);
    } else {
      const FocalPlaneSamples e = pixel_energy_samples(optics, g, s, half, f, otf);
      m.core.assign(static_cast<std::size_t>(offsets * offsets * box * box), 0.0f);
      gather(e, s, offsets, 1, c, [&](std::int64_t ix, std::int64_t iy, std::int64_t dx, std::int64_t dy, double v) {
        m.core[static_cast<std::size_t>((iy * offsets + ix) * box * box + (dy + c) * box + dx + c)] =
            static_cast<float>(v);
      });
    }
  }
  if (m.has_tail()) {
    // E at half-pixel offsets over the window: the direct tail (if it fits
    // the bound; zero on the core box) and, at whole pixels, E0 for the
    // multilevel tail. Offsets i = 0..2 <-> phi = -1/2 + i / 2: j = 2 d + 1 - i.
    const std::int64_t s = PointSourceModel::tail_steps, offsets = s + 1, half = H * s + s, window = 2 * H + 1;
    const bool direct = static_cast<double>(tail_bytes(H)) <= budget / 4;
    if (direct) m.tail.assign(static_cast<std::size_t>(offsets * offsets * window * window), 0.0f);
    FocalPlaneSamples e0;
    e0.size = window;
    e0.step_x_cm = g.pitch_x_cm;
    e0.step_y_cm = g.pitch_y_cm;
    e0.values.assign(static_cast<std::size_t>(window * window), 0.0);
    const FocalPlaneSamples e = pixel_energy_samples(optics, g, s, half, f, otf);
    for (std::int64_t dy = -H; dy <= H; ++dy)  // phi = 0: sample j = d s
      for (std::int64_t dx = -H; dx <= H; ++dx)
        e0.values[static_cast<std::size_t>((dy + H) * window + dx + H)] = e.at(dx * s, dy * s);
    if (direct)
      gather(e, s, offsets, 0, H, [&](std::int64_t ix, std::int64_t iy, std::int64_t dx, std::int64_t dy, double v) {
        if (std::abs(dx) > c || std::abs(dy) > c)  // the core box is the core's
          m.tail[static_cast<std::size_t>((iy * offsets + ix) * window * window + (dy + H) * window + dx + H)] =
              static_cast<float>(v);
      });
    if (m.corners)
      half_pixel_corner_terms(*m.corners, m.pixel_x_lf, m.pixel_y_lf, H,
                              [&](std::int64_t ix, std::int64_t iy, std::int64_t dx, std::int64_t dy, double v) {
                                if (ix == 1 && iy == 1) e0.values[static_cast<std::size_t>((dy + H) * window + dx + H)] += v;
                                if (direct && (std::abs(dx) > c || std::abs(dy) > c))
                                  m.tail[static_cast<std::size_t>((iy * offsets + ix) * window * window +
                                                                  (dy + H) * window + dx + H)] += static_cast<float>(v);
                              });
    m.halo = halo_levels(e0, m.taper_start, f.point_table_fft_sizes == TableFftSizes::fitted);
  }
  m.streak_steps_per_pixel_x =
      std::max(f.streak_steps_per_pixel, f.streak_steps_per_lambda_f * g.pitch_x_cm / lambda_f_cm);
  m.streak_steps_per_pixel_y =
      std::max(f.streak_steps_per_pixel, f.streak_steps_per_lambda_f * g.pitch_y_cm / lambda_f_cm);
  m.build_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return m;
}

}  // namespace eoir::sensor
