#include "sensor/system_psf.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/fftw_plans.hpp"  // the process-wide plan cache (planning is not thread-safe)
#include "core/parallel_ranges.hpp"

namespace eoir::sensor {
namespace {

constexpr std::int64_t kFoldRowsPerThread = 64;  // a thread's wake-up (~50 us) against its rows of the fold
constexpr std::int64_t kKeptFftSize = 1024;        // integrated_psf keeps its arrays up to this size

double sinc_pi(double x) {  // sin(pi x) / (pi x)
  const double a = constants::pi * x;
  return std::abs(a) < 1.0e-8 ? 1.0 : std::sin(a) / a;
}

// Frequency of FFT index i on an n-point grid of spacing dx (cycles/cm).
double frequency(std::int64_t i, std::int64_t n, double dx_cm) {
  const std::int64_t signed_index = i <= n / 2 ? i : i - n;
  return static_cast<double>(signed_index) / (static_cast<double>(n) * dx_cm);
}

// One frequency at which the spectrum is evaluated for an FFT bin: the bin's
// own frequency or one of its aliases xi + m / dx, with xi^2 and the separable
// factor of its axis (cell footprint sinc times the shift phase).
struct AxisFrequency {
  double xi_squared;
  std::complex<double> factor;
};

// For every bin of one axis, the frequencies xi_bin + m / d with |xi| below
// the cutoff. With d <= lambda F# / 2 that is the bin alone (or nothing);
// with a coarser d the band-limited spectrum is folded onto the bins, which
// is what sampling the focal plane at spacing d does (Poisson summation).
std::vector<std::vector<AxisFrequency>> axis_frequencies(std::int64_t bins, std::int64_t n, double d_cm,
                                                         double cutoff, double cell_cm, double offset_cm) {
  std::vector<std::vector<AxisFrequency>> out(static_cast<std::size_t>(bins));
  const double period = 1.0 / d_cm;  // cycles/cm between aliases
  for (std::int64_t b = 0; b < bins; ++b) {
    const double base = frequency(b, n, d_cm);
    const auto m_low = static_cast<std::int64_t>(std::ceil((-cutoff - base) / period));
    const auto m_high = static_cast<std::int64_t>(std::floor((cutoff - base) / period));
    for (std::int64_t m = m_low; m <= m_high; ++m) {
      const double xi = base + static_cast<double>(m) * period;
      if (std::abs(xi) >= cutoff) continue;
      out[static_cast<std::size_t>(b)].push_back(
          {xi * xi, sinc_pi(xi * cell_cm) * std::polar(1.0, -2.0 * constants::pi * xi * offset_cm)});
    }
  }
  return out;
}

// FFT points per output step along one axis. Nyquist-fine (fft_subdivisions)
// when the FFT period n dx then spans the window plus a margin of
// `period_margin_steps` (aliases of the PSF tails land that far out);
// otherwise coarser (down to 1, the spectrum folded) so that it does. The
// margin shrinks (to 1) if folding would evaluate the OTF more than
// max(4 n^2, 2^22) times (~50 ms; the pixel is then over a hundred lambda F#
// and the tails that alias are small).
std::int64_t subdivisions_for(const OpticsModel& optics, double step_cm, std::int64_t min_subdivisions,
                              std::int64_t size, const PsfNumerics& numerics) {
  const std::int64_t n = numerics.fft_size, period_margin_steps = numerics.alias_margin_steps;
  const std::int64_t nyquist = fft_subdivisions(optics, step_cm, min_subdivisions);
  const double steps_per_cutoff = step_cm * optics.cutoff_cycles_per_cm();
  std::int64_t period_steps = size + period_margin_steps;
  auto folded_evaluations = [&](std::int64_t steps) {  // OTF points inside the cutoff disc
    const double period_times_cutoff = static_cast<double>(steps) * steps_per_cutoff;
    return constants::pi * period_times_cutoff * period_times_cutoff;
  };
  const double budget = std::max(4.0 * static_cast<double>(n) * static_cast<double>(n), numerics.fold_budget);
  while (period_steps > size + 1 && folded_evaluations(period_steps) > budget) --period_steps;
  return std::max<std::int64_t>(1, std::min(nyquist, n / period_steps));
}

// The inverse of the half spectrum `in` (n x (n/2 + 1), row-major; its
// columns transformed in place) at the window's rows and columns only:
// along y for every column, then along x for the rows the window reads;
// out[r * size + c] = the real sample (rows[r], cols[c]). Both passes in
// parallel (columns in blocks of kColumnBlock, which keeps each block's
// first element as aligned as `in`). The same transform as the 2-D c2r,
// rounding aside, in about (1 + size / n) / 2 of its work.
void window_rows_c2r(fftw_complex* in, std::int64_t n, const std::vector<std::int64_t>& rows,
                     const std::vector<std::int64_t>& cols, double* out) {
  constexpr std::int64_t kColumnBlock = 8;
  const std::int64_t nc = n / 2 + 1, blocks = (nc + kColumnBlock - 1) / kColumnBlock;
  const auto width = static_cast<int>(nc);
  parallel_ranges(
      blocks, 0,
      [&](std::int64_t b0, std::int64_t b1) {
        const fftw_plan whole = fftw::columns(static_cast<int>(n), kColumnBlock, width, FFTW_BACKWARD);
        for (std::int64_t b = b0; b < b1; ++b) {
          const std::int64_t first = b * kColumnBlock, count = std::min(kColumnBlock, nc - first);
          const fftw_plan plan = count == kColumnBlock
                                     ? whole
                                     : fftw::columns(static_cast<int>(n), static_cast<int>(count), width, FFTW_BACKWARD);
          fftw_execute_dft(plan, in + first, in + first);
        }
      },
      2);
  const auto size = static_cast<std::int64_t>(cols.size());
  const fftw_plan backward = fftw::row_c2r(static_cast<int>(n));
  parallel_ranges(
      size, 0,
      [&](std::int64_t r0, std::int64_t r1) {
        const fftw::ComplexBuffer buffer = fftw::complex_buffer(static_cast<std::size_t>(nc));  // aligned as planned
        double* const real = reinterpret_cast<double*>(buffer.get());
        for (std::int64_t r = r0; r < r1; ++r) {
          std::copy_n(&in[static_cast<std::size_t>(rows[static_cast<std::size_t>(r)] * nc)][0], 2 * nc, real);
          fftw_execute_dft_c2r(backward, buffer.get(), real);
          double* to = out + r * size;
          for (std::int64_t c = 0; c < size; ++c) to[c] = real[cols[static_cast<std::size_t>(c)]];
        }
      },
      16);
}

// The core: the PSF convolved with a cell_x x cell_y box (a unit-area delta
// when cell_* = 0), shifted by (offset_x, offset_y), sampled at multiples of
// (step_x, step_y) in a window of odd `size`.
FocalPlaneSamples integrated_psf(const OpticsModel& optics, double cell_x_cm, double cell_y_cm, double step_x_cm,
                                 double step_y_cm, std::int64_t size, double offset_x_cm, double offset_y_cm,
                                 std::int64_t min_subdivisions, const PsfNumerics& numerics) {
  const std::int64_t fft_size = numerics.fft_size;
  if (numerics.fitted_fft_size ? !(fft_size >= 64 && fft_size <= 4096 && fft_size % 2 == 0)
                               : !valid_psf_grid_size(fft_size))
    throw Error(Status::out_of_range, std::string(numerics.fitted_fft_size ? "psf table FFT size: must be even"
                                                                           : "psf_grid_size: must be a power of two") +
                                          " in [64, 4096], got " + std::to_string(fft_size));
  if (size < 1 || size % 2 == 0)
    throw Error(Status::out_of_range, "psf window: must be odd and >= 1, got " + std::to_string(size));
  const std::int64_t n = fft_size;
  // The spatial period n dx must exceed the window by at least one step, so
  // that aliased copies of the window's cells lie beyond it.
  if (size + 1 > n)
    throw Error(Status::out_of_range, "psf_grid_size: " + std::to_string(n) + " is too small for a window of " +
                                          std::to_string(size) + " samples");
  const std::int64_t kx = subdivisions_for(optics, step_x_cm, min_subdivisions, size, numerics);
  const std::int64_t ky = subdivisions_for(optics, step_y_cm, min_subdivisions, size, numerics);
  const double dx = step_x_cm / static_cast<double>(kx);
  const double dy = step_y_cm / static_cast<double>(ky);
  const std::int64_t nc = n / 2 + 1;  // complex columns of the c2r input
  const double cutoff = optics.cutoff_cycles_per_cm();
  const double cutoff2 = cutoff * cutoff;
  const auto fx = axis_frequencies(nc, n, dx, cutoff, cell_x_cm, offset_x_cm);
  const auto fy = axis_frequencies(n, n, dy, cutoff, cell_y_cm, offset_y_cm);

  // The OTF is radial: tabulate it once on [0, cutoff] and interpolate
  // linearly (the fold below evaluates it up to millions of times; the table
  // error is below 1e-6 of the OTF's peak, where eq. 34 has its
  // (1 - nu)^(3/2) edge).
  const std::int64_t table_size = numerics.otf_table_size;
  const bool given = numerics.otf_table && numerics.otf_table->size() == static_cast<std::size_t>(table_size + 2);
  const std::vector<double> own = given ? std::vector<double>{} : radial_otf_table(optics, table_size);
  const std::vector<double>& otf_table = given ? *numerics.otf_table : own;
  const double table_scale = static_cast<double>(table_size) / cutoff;
  auto otf_at = [&](double rho) {
    const double u = rho * table_scale;
    const auto k = static_cast<std::size_t>(u);
    const double f = u - static_cast<double>(k);
    return otf_table[k] + f * (otf_table[k + 1] - otf_table[k]);
  };

  // The transform's arrays, kept per thread up to kKeptFftSize^2 points
  // (17 MB at most): a fresh pair costs a table build its page faults, a
  // quarter of its time.
  struct Arrays {
    fftw::ComplexBuffer in;
    fftw::RealBuffer out;
    std::int64_t n = 0;  // the largest transform they hold
  };
  thread_local Arrays kept;
  Arrays fresh;
  Arrays& arrays = n <= kKeptFftSize ? kept : fresh;
  if (arrays.n < n) {
    arrays.in = fftw::complex_buffer(static_cast<std::size_t>(n * nc));
    arrays.out.reset();
    arrays.n = n;
  }
  // (fitted tables transform the window's rows only: no n x n output)
  if (!numerics.fitted_fft_size && !arrays.out)
    arrays.out = fftw::real_buffer(static_cast<std::size_t>(arrays.n * arrays.n));
  fftw_complex* const in = arrays.in.get();
  double* const out = arrays.out.get();
  // Sum over the frequency grid times d xi_x d xi_y = 1 / (n^2 dx dy): the
  // inverse transform of eq. 40 as a Riemann sum. A cell footprint of area
  // a b integrates the PSF over the cell, so it carries the factor a b.
  const double cell_area = (cell_x_cm > 0 ? cell_x_cm : 1.0) * (cell_y_cm > 0 ? cell_y_cm : 1.0);
  const double scale = cell_area / (static_cast<double>(n) * static_cast<double>(n) * dx * dy);
  // The OTF is radial and row n - j holds the negated frequencies of row j
  // (with conjugate factors), so each OTF value serves both rows.
  // Rows in parallel (each writes rows j and n - j only: the same result
  // for any thread count).
  parallel_ranges(
      n / 2 + 1, 0,
      [&](std::int64_t j_begin, std::int64_t j_end) {
        for (std::int64_t j = j_begin; j < j_end; ++j) {
          const std::int64_t mirror = (n - j) % n;
          const bool has_mirror = j != 0 && j != n / 2;
          const auto& row = fy[static_cast<std::size_t>(j)];
          for (std::int64_t i = 0; i < nc; ++i) {
            std::complex<double> value(0.0), mirrored(0.0);
            for (const AxisFrequency& ax : fx[static_cast<std::size_t>(i)]) {
              for (const AxisFrequency& ay : row) {
                const double r2 = ax.xi_squared + ay.xi_squared;
                if (r2 >= cutoff2) continue;
                const std::complex<double> t = otf_at(std::sqrt(r2)) * ax.factor;
                value += t * ay.factor;
                mirrored += t * std::conj(ay.factor);
              }
            }
            in[static_cast<std::size_t>(j * nc + i)][0] = scale * value.real();
            in[static_cast<std::size_t>(j * nc + i)][1] = scale * value.imag();
            if (has_mirror) {
              in[static_cast<std::size_t>(mirror * nc + i)][0] = scale * mirrored.real();
              in[static_cast<std::size_t>(mirror * nc + i)][1] = scale * mirrored.imag();
            }
          }
        }
      },
      kFoldRowsPerThread);
  FocalPlaneSamples result;
  result.size = size;
  result.step_x_cm = step_x_cm;
  result.step_y_cm = step_y_cm;
  result.values.resize(static_cast<std::size_t>(size * size));
  const std::int64_t half = size / 2;
  std::vector<std::int64_t> cols(static_cast<std::size_t>(size)), rows(static_cast<std::size_t>(size));
  for (std::int64_t i = -half; i <= half; ++i) {
    cols[static_cast<std::size_t>(i + half)] = ((i * kx) % n + n) % n;
    rows[static_cast<std::size_t>(i + half)] = ((i * ky) % n + n) % n;
  }
  if (numerics.fitted_fft_size) {
    window_rows_c2r(in, n, rows, cols, result.values.data());
    return result;
  }
  // Thread-safe: a kept plan executed on this call's own aligned arrays.
  fftw_execute_dft_c2r(fftw::c2r_2d(static_cast<int>(n), static_cast<int>(n)), in, out);
  for (std::int64_t iy = 0; iy < size; ++iy) {
    const double* row = out + rows[static_cast<std::size_t>(iy)] * n;
    double* to = &result.values[static_cast<std::size_t>(iy * size)];
    for (std::int64_t i = 0; i < size; ++i) to[i] = row[cols[static_cast<std::size_t>(i)]];
  }
  return result;
}

}  // namespace

double FocalPlaneSamples::sum() const {
  double s = 0;
  for (double v : values) s += v;
  return s;
}

bool valid_psf_grid_size(std::int64_t n) { return n >= 64 && n <= 4096 && (n & (n - 1)) == 0; }

std::int64_t fft_subdivisions(const OpticsModel& optics, double step_cm, std::int64_t min_subdivisions) {
  const double nyquist_spacing_cm = 0.5 * optics.diffraction_wavelength_cm * optics.f_number;
  const auto k = static_cast<std::int64_t>(std::ceil(step_cm / nyquist_spacing_cm * (1.0 - 1.0e-12)));
  return std::max(k, min_subdivisions);
}

FocalPlaneSamples sampled_psf(const OpticsModel& optics, double spacing_x_cm, double spacing_y_cm,
                              std::int64_t size, const PsfNumerics& numerics, bool cell_integrated) {
  FocalPlaneSamples psf =
      integrated_psf(optics, cell_integrated ? spacing_x_cm : 0.0, cell_integrated ? spacing_y_cm : 0.0,
                     spacing_x_cm, spacing_y_cm, size, 0.0, 0.0, 1, numerics);
  const double total = psf.sum();
  for (double& v : psf.values) v /= total;
  return psf;
}

FocalPlaneSamples energy_on_detector(const OpticsModel& optics, double pitch_x_cm, double pitch_y_cm,
                                     std::int64_t window, double offset_x_cm, double offset_y_cm,
                                     const PsfNumerics& numerics) {
  // At least 4 FFT points per pixel (the p / 4 sample interval of eqs. 13-14)
  // unless the spectrum is folded (see subdivisions_for).
  return integrated_psf(optics, pitch_x_cm, pitch_y_cm, pitch_x_cm, pitch_y_cm, window, offset_x_cm, offset_y_cm,
                        4, numerics);
}

FocalPlaneSamples pixel_integrated_psf(const OpticsModel& optics, double pitch_x_cm, double pitch_y_cm,
                                       double step_x_cm, double step_y_cm, std::int64_t size, double centre_x_cm,
                                       double centre_y_cm, const PsfNumerics& numerics) {
  // Sample ix of integrated_psf is (PSF conv box)(ix step - offset): offset = -centre.
  return integrated_psf(optics, pitch_x_cm, pitch_y_cm, step_x_cm, step_y_cm, size, -centre_x_cm, -centre_y_cm, 1,
                        numerics);
}

std::vector<double> radial_otf_table(const OpticsModel& optics, std::int64_t otf_table_size) {
  const double cutoff = optics.cutoff_cycles_per_cm();
  std::vector<double> otf_table(static_cast<std::size_t>(otf_table_size + 2), 0.0);
  parallel_ranges(
      otf_table_size + 1, 0,
      [&](std::int64_t begin, std::int64_t end) {
        for (std::int64_t t = begin; t < end; ++t)
          otf_table[static_cast<std::size_t>(t)] =
              optics.system(cutoff * static_cast<double>(t) / static_cast<double>(otf_table_size));
      },
      4096);
  return otf_table;
}

std::vector<double> pixel_integrated_lsf(const OpticsModel& optics, double pitch_cm, double step_cm, std::int64_t half,
                                         double centre_cm, double period_cm, std::int64_t otf_table_size) {
  return pixel_integrated_lsf(optics, pitch_cm, step_cm, half, centre_cm, period_cm,
                              radial_otf_table(optics, otf_table_size));
}

std::vector<double> pixel_integrated_lsf(const OpticsModel& optics, double pitch_cm, double step_cm, std::int64_t half,
                                         double centre_cm, double period_cm, const std::vector<double>& otf_table) {
  const auto otf_table_size = static_cast<std::int64_t>(otf_table.size()) - 2;
  const std::int64_t k = fft_subdivisions(optics, step_cm, 1);
  const double dx = step_cm / static_cast<double>(k);
  const double span_cm = static_cast<double>(2 * half + 1) * step_cm;
  const double period = std::max(period_cm, 2.0 * span_cm);
  const auto wanted = static_cast<std::int64_t>(std::ceil(period / dx));
  if (wanted > (std::int64_t{1} << 28))
    throw Error(Status::out_of_range, "psf window: a line-spread FFT of " + std::to_string(wanted) + " points");
  const std::int64_t n = 2 * static_cast<std::int64_t>(fftw::good_size(static_cast<int>((wanted + 1) / 2)));
  const std::int64_t bins = n / 2 + 1;
  const double cutoff = optics.cutoff_cycles_per_cm();
  // The radial OTF tabulated on [0, cutoff] as integrated_psf does.
  const double table_scale = static_cast<double>(otf_table_size) / cutoff;
  const fftw::ComplexBuffer spectrum = fftw::complex_buffer(static_cast<std::size_t>(bins));
  // Riemann sum over d xi = 1 / (n dx) of OTF(xi, 0) pitch sinc(xi pitch)
  // e^(2 pi i xi centre): sample i is the pixel-integrated LSF at i dx + centre.
  const double scale = pitch_cm / (static_cast<double>(n) * dx);
  for (std::int64_t b = 0; b < bins; ++b) {
    const double xi = static_cast<double>(b) / (static_cast<double>(n) * dx);
    double value = 0;
    if (xi < cutoff) {
      const double u = xi * table_scale;
      const auto t = static_cast<std::size_t>(u);
      const double frac = u - static_cast<double>(t);
      value = scale * (otf_table[t] + frac * (otf_table[t + 1] - otf_table[t])) * sinc_pi(xi * pitch_cm);
    }
    const double phase = 2.0 * constants::pi * xi * centre_cm;
    const std::complex<double> v(value * std::cos(phase), value * std::sin(phase));
    spectrum[static_cast<std::size_t>(b)][0] = v.real();
    spectrum[static_cast<std::size_t>(b)][1] = v.imag();
  }
  // In place: the row holds n reals in 2 (n/2 + 1).
  fftw_execute_dft_c2r(fftw::row_c2r(static_cast<int>(n)), spectrum.get(), reinterpret_cast<double*>(spectrum.get()));
  const double* samples = reinterpret_cast<const double*>(spectrum.get());
  std::vector<double> out(static_cast<std::size_t>(2 * half + 1));
  for (std::int64_t j = -half; j <= half; ++j)
    out[static_cast<std::size_t>(j + half)] = samples[static_cast<std::size_t>(((j * k) % n + n) % n)];
  return out;
}

double ensquared_energy(const OpticsModel& optics, double pitch_x_cm, double pitch_y_cm,
                        const PsfNumerics& numerics) {
  return energy_on_detector(optics, pitch_x_cm, pitch_y_cm, 1, 0.0, 0.0, numerics).values[0];
}

}  // namespace eoir::sensor
