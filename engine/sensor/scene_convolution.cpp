#include "sensor/scene_convolution.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/parallel_ranges.hpp"
#include "sensor/sensor_model.hpp"

namespace eoir::sensor {
namespace {

using Complex = std::complex<double>;

// Columns transformed together in step 2: a block of rows x 8 complex values
// (140 kB at 1120 rows) stays in cache from the forward transform through the
// OTF product and the fold.
constexpr int column_block = 8;
// Rows (step 1) and pixel rows (step 3) a thread takes at a time.
constexpr std::int64_t row_chunk = 16, pixel_row_chunk = 4;

// FFT frequency (cycles per unit of the spacing) of index i on n points.
double frequency(int i, int n, double spacing) {
  const int k = i <= n / 2 ? i : i - n;
  return static_cast<double>(k) / (static_cast<double>(n) * spacing);
}

// Phi[i] = sum_{j<k} exp(2 pi i i (offset + j) / n) for i in [0, n): the
// spectrum's weight that sums k samples from offset on, on n points (the
// exponent reduced mod n in integers).
std::vector<Complex> box_sum_phases(int n, std::int64_t offset, std::int64_t k) {
  std::vector<Complex> phi(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    Complex sum = 0;
    for (std::int64_t j = 0; j < k; ++j) {
      const std::int64_t turns = (static_cast<std::int64_t>(i) * (offset + j)) % n;
      const double angle = 2.0 * constants::pi * static_cast<double>(turns) / static_cast<double>(n);
      sum += Complex(std::cos(angle), std::sin(angle));
    }
    phi[static_cast<std::size_t>(i)] = sum;
  }
  return phi;
}

void build(SceneConvolutionCache& cache, const SensorModel& model, const geometry::SampleGrid& g, unsigned threads) {
  cache.grid_cols = g.width();
  cache.grid_rows = g.height();
  const int w = static_cast<int>(g.width()), h = static_cast<int>(g.height()), k = static_cast<int>(g.per_pixel);
  cache.pad = static_cast<int>(std::lround(model.fidelity().fft_padding * static_cast<double>(g.guard_samples())));
  // Whole pixels on the transform's period, so the pixel grid folds onto it.
  cache.fft_cols = k * fftw::good_size((w + 2 * cache.pad + k - 1) / k);
  cache.fft_rows = k * fftw::good_size((h + 2 * cache.pad + k - 1) / k);
  const int rows = cache.fft_rows, cols = cache.fft_cols, half = cols / 2 + 1;
  const double dx = g.pitch_x_cm / k, dy = g.pitch_y_cm / k;
  const double scale = 1.0 / (static_cast<double>(rows) * static_cast<double>(cols));
  cache.otf_scaled.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(half));
  std::vector<int> passband(static_cast<std::size_t>(rows), 0);  // per row: 1 + its last nonzero column
  parallel_ranges(rows, threads, [&](std::int64_t r0, std::int64_t r1) {
    for (auto r = static_cast<int>(r0); r < r1; ++r) {
      const double fy = frequency(r, rows, dy);
      for (int c = 0; c < half; ++c) {
        const double fx = static_cast<double>(c) / (cols * dx);
        const double otf = model.optics.system(std::sqrt(fx * fx + fy * fy)) * scale;
        cache.otf_scaled[static_cast<std::size_t>(r) * half + c] = otf;
        if (otf != 0.0) passband[static_cast<std::size_t>(r)] = c + 1;
      }
    }
  }, 16);
  cache.passband_cols = *std::max_element(passband.begin(), passband.end());
  // The field's first sample is pad + guard into the buffer on both axes.
  const std::int64_t first = cache.pad + g.guard_samples();
  cache.row_phases = box_sum_phases(rows, first, k);
  for (Complex& phi : cache.row_phases) phi /= static_cast<double>(k) * k;  // the pixel mean (eq. 49)
  cache.column_phases = box_sum_phases(cols, first, k);
  cache.buffer = fftw::complex_buffer(static_cast<std::size_t>(rows) * static_cast<std::size_t>(half));
  cache.folded = fftw::complex_buffer(static_cast<std::size_t>(g.pixels_y) * static_cast<std::size_t>(half));
}

// FFTW executes a plan on another array only at the alignment it was planned
// for; every row and column block here starts on a 16-byte boundary.
void check_alignment(const void* p) {
  if (fftw_alignment_of(static_cast<double*>(const_cast<void*>(p))) != 0)
    throw Error(Status::internal, "convolution: a transform row is not aligned for FFTW");
}

}  // namespace

std::vector<double> pixel_radiance(const SensorModel& model, const radiometry::RadianceImage& scene,
                                   unsigned threads, std::vector<double> storage) {
  SceneConvolutionCache& cache = *model.scene_convolution;
  const geometry::SampleGrid& g = scene.grid;
  std::call_once(cache.built, [&] { build(cache, model, g, threads); });
  if (g.width() != cache.grid_cols || g.height() != cache.grid_rows)
    throw Error(Status::internal, "convolution: the scene's sample grid is not the sensor model's");
  const std::int64_t nx = g.pixels_x, ny = g.pixels_y, k = g.per_pixel;
  std::vector<double> out = std::move(storage);
  out.resize(static_cast<std::size_t>(nx * ny));  // every pixel is written below
  std::unique_lock<std::mutex> lock(cache.buffer_mutex);
  const int w = static_cast<int>(g.width()), h = static_cast<int>(g.height());
  const int rows = cache.fft_rows, cols = cache.fft_cols, half = cols / 2 + 1, pad = cache.pad;
  const int pixel_rows = rows / static_cast<int>(k), pixel_cols = cols / static_cast<int>(k);
  const int passband = cache.passband_cols;
  const std::size_t stride = 2 * static_cast<std::size_t>(half);  // reals per row in place
  fftw_complex* spectrum = cache.buffer.get();
  double* real = reinterpret_cast<double*>(spectrum);
  const std::vector<double>& radiance = scene.radiance_W_cm2_sr;

  // Step 1: rows filled and transformed, in chunks taken as threads finish
  // (constant rows cost next to nothing). Each thread notes whether all its
  // rows were constant, and at which value, to find a uniform scene.
  struct Constancy {
    bool seen = false, constant = true;
    double value = 0;
  };
  std::vector<Constancy> constancy(parallel_range_count(rows, threads, row_chunk));
  parallel_chunks(rows, threads, row_chunk, [&](unsigned t, std::int64_t r0, std::int64_t r1) {
    Constancy& mine = constancy[t];
    fftw_plan forward = nullptr;  // asked for on the chunk's first row that needs it
    for (auto r = static_cast<int>(r0); r < r1; ++r) {
      const int source_row = std::clamp(r - pad, 0, h - 1);
      double* row = real + static_cast<std::size_t>(r) * stride;
      if (r > r0 && source_row == std::clamp(r - 1 - pad, 0, h - 1)) {  // padding: the row above again
        std::memcpy(row, row - stride, stride * sizeof(double));
        continue;
      }
      const double* source = radiance.data() + static_cast<std::size_t>(source_row) * w;
      const bool constant = std::all_of(source + 1, source + w, [v = source[0]](double x) { return x == v; });
      if (!mine.seen) mine.value = source[0];
      mine.seen = true;
      mine.constant = mine.constant && constant && source[0] == mine.value;
      if (constant) {  // the DFT of n values v: n v at zero frequency
        std::fill(row, row + stride, 0.0);
        row[0] = source[0] * cols;
        continue;
      }
      std::fill(row, row + pad, source[0]);
      std::copy(source, source + w, row + pad);
      std::fill(row + pad + w, row + cols, source[w - 1]);
      if (!forward) forward = fftw::row_r2c(cols);
      check_alignment(row);
      fftw_execute_dft_r2c(forward, row, reinterpret_cast<fftw_complex*>(row));
    }
  });
  const double first = radiance.front();
  if (std::all_of(constancy.begin(), constancy.end(),
                  [first](const Constancy& c) { return !c.seen || (c.constant && c.value == first); })) {
    std::fill(out.begin(), out.end(), first);
    return out;
  }

  // Step 2: each block of passband columns transformed, times the OTF and
  // the pixel rows' box-sum phases, folded onto the rows / k pixel-row
  // frequencies and transformed back there: the spectrum of the field's
  // pixel rows (sums over their k sample rows), kept for step 3. Each thread
  // takes a contiguous range of blocks (neighbouring blocks share cache lines).
  fftw_complex* folded = cache.folded.get();
  parallel_ranges(passband, threads, [&](std::int64_t c0, std::int64_t c1) {
    const fftw_plan plans[2] = {fftw::columns(rows, column_block, half, FFTW_FORWARD),
                                fftw::columns(pixel_rows, column_block, column_block, FFTW_BACKWARD)};
    fftw::ComplexBuffer block_buffer = fftw::complex_buffer(static_cast<std::size_t>(pixel_rows) * column_block);
    fftw_complex* block_spectrum = block_buffer.get();
    for (auto block = static_cast<int>(c0); block < c1; block += column_block) {
      const int count = std::min(column_block, static_cast<int>(c1) - block);
      const bool whole = count == column_block;
      fftw_complex* columns = spectrum + block;
      check_alignment(columns);
      fftw_execute_dft(whole ? plans[0] : fftw::columns(rows, count, half, FFTW_FORWARD), columns, columns);
      std::fill_n(&block_spectrum[0][0], 2 * static_cast<std::size_t>(pixel_rows) * count, 0.0);
      for (int r = 0; r < rows; ++r) {
        const Complex phase = cache.row_phases[static_cast<std::size_t>(r)];
        const std::size_t i0 = static_cast<std::size_t>(r) * half + static_cast<std::size_t>(block);
        const std::size_t o0 = static_cast<std::size_t>(r % pixel_rows) * count;
        for (int j = 0; j < count; ++j) {  // written out: std::complex's product checks for NaNs
          const double gain = cache.otf_scaled[i0 + j];
          const double re = gain * phase.real(), im = gain * phase.imag();
          const double* y = spectrum[i0 + j];
          double* z = block_spectrum[o0 + j];
          z[0] += y[0] * re - y[1] * im;
          z[1] += y[0] * im + y[1] * re;
        }
      }
      fftw_execute_dft(whole ? plans[1] : fftw::columns(pixel_rows, count, count, FFTW_BACKWARD), block_spectrum,
                       block_spectrum);
      for (std::int64_t m = 0; m < ny; ++m)
        std::memcpy(&folded[static_cast<std::size_t>(m) * half + static_cast<std::size_t>(block)],
                    &block_spectrum[static_cast<std::size_t>(m) * count], sizeof(fftw_complex) * count);
    }
  }, column_block);

  // Step 3: each pixel row's spectrum weighted by the pixel columns' box-sum
  // phases, folded onto the cols / k pixel-column frequencies (the columns
  // past cols / 2 are the conjugates of those below it; past the passband,
  // zero) and transformed back: the pixel means.
  const int pixel_half = pixel_cols / 2 + 1;
  const fftw_plan backward = fftw::row_c2r(pixel_cols);
  std::vector<fftw::ComplexBuffer> row_buffers(parallel_range_count(ny, threads, pixel_row_chunk));  // one a thread
  parallel_chunks(ny, threads, pixel_row_chunk, [&](unsigned t, std::int64_t m0, std::int64_t m1) {
    if (!row_buffers[t]) row_buffers[t] = fftw::complex_buffer(static_cast<std::size_t>(pixel_half));
    fftw_complex* row = row_buffers[t].get();
    for (std::int64_t m = m0; m < m1; ++m) {
      const fftw_complex* spectrum_row = folded + static_cast<std::size_t>(m) * half;
      for (int q = 0; q < pixel_half; ++q) {
        double re = 0, im = 0;
        for (int c = q; c < cols; c += pixel_cols) {
          const bool below = c <= cols / 2;
          const int source = below ? c : cols - c;
          if (source >= passband) continue;
          const double v_re = spectrum_row[source][0], v_im = below ? spectrum_row[source][1] : -spectrum_row[source][1];
          const Complex& phi = cache.column_phases[static_cast<std::size_t>(c)];
          re += v_re * phi.real() - v_im * phi.imag();
          im += v_re * phi.imag() + v_im * phi.real();
        }
        row[q][0] = re;
        row[q][1] = im;
      }
      double* samples = reinterpret_cast<double*>(row);
      fftw_execute_dft_c2r(backward, row, samples);
      std::copy_n(samples, nx, out.data() + m * nx);
    }
  });
  return out;
}

}  // namespace eoir::sensor
