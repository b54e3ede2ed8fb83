#include "sensor/scene_convolution.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/parallel_ranges.hpp"
#include "core/scratch_file.hpp"
#include "sensor/catmull_rom.hpp"
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

// The transform's padding and size for a grid: whole pixels on the
// transform's period, so the pixel grid folds onto it.
struct TransformShape {
  int pad = 0, cols = 0, rows = 0;
};
TransformShape transform_shape(const SensorModel& model, const geometry::SampleGrid& g) {
  const int w = static_cast<int>(g.width()), h = static_cast<int>(g.height()), k = static_cast<int>(g.per_pixel);
  TransformShape t;
  t.pad = static_cast<int>(std::lround(model.fidelity().fft_padding * static_cast<double>(g.guard_samples())));
  t.cols = k * fftw::good_size((w + 2 * t.pad + k - 1) / k);
  t.rows = k * fftw::good_size((h + 2 * t.pad + k - 1) / k);
  return t;
}

// The transform's size, padding and box-sum phases (both ways of making a frame).
void build_shape(SceneConvolutionCache& cache, const SensorModel& model, const geometry::SampleGrid& g) {
  cache.grid_cols = g.width();
  cache.grid_rows = g.height();
  const int k = static_cast<int>(g.per_pixel);
  const TransformShape t = transform_shape(model, g);
  cache.pad = t.pad;
  cache.fft_cols = t.cols;
  cache.fft_rows = t.rows;
  // The field's first sample is pad + guard into the buffer on both axes.
  const std::int64_t first = cache.pad + g.guard_samples();
  cache.row_phases = box_sum_phases(cache.fft_rows, first, k);
  for (Complex& phi : cache.row_phases) phi /= static_cast<double>(k) * k;  // the pixel mean (eq. 49)
  cache.column_phases = box_sum_phases(cache.fft_cols, first, k);
}

// The whole frame's OTF grid and buffers.
void build_whole(SceneConvolutionCache& cache, const SensorModel& model, const geometry::SampleGrid& g,
                 unsigned threads) {
  const int k = static_cast<int>(g.per_pixel);
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
  cache.buffer = fftw::complex_buffer(static_cast<std::size_t>(rows) * static_cast<std::size_t>(half));
  cache.folded = fftw::complex_buffer(static_cast<std::size_t>(g.pixels_y) * static_cast<std::size_t>(half));
}

// Strips: the OTF against |f| on kStripOtfNodes nodes to the diffraction
// cutoff (it is zero beyond, eq. 34), and the passband: the OTF is radial and
// nowhere nonzero beyond its last nonzero column on the fy = 0 row.
constexpr int kStripOtfNodes = 1 << 20;
void build_strips(SceneConvolutionCache& cache, const SensorModel& model, const geometry::SampleGrid& g,
                  unsigned threads) {
  const int k = static_cast<int>(g.per_pixel), cols = cache.fft_cols, half = cols / 2 + 1;
  const double dx = g.pitch_x_cm / k;
  cache.strip_passband_cols = 0;
  for (int c = 0; c < half; ++c)
    if (model.optics.system(static_cast<double>(c) / (cols * dx)) != 0.0) cache.strip_passband_cols = c + 1;
  cache.otf_cutoff_cycles_per_cm = model.optics.cutoff_cycles_per_cm();
  cache.otf_node_step = cache.otf_cutoff_cycles_per_cm / kStripOtfNodes;
  // nodes -1 .. kStripOtfNodes + 2 (the cubic's neighbours; zero beyond the cutoff)
  cache.otf_radial.resize(static_cast<std::size_t>(kStripOtfNodes) + 4);
  parallel_ranges(static_cast<std::int64_t>(cache.otf_radial.size()), threads, [&](std::int64_t a, std::int64_t b) {
    for (std::int64_t i = a; i < b; ++i)
      cache.otf_radial[static_cast<std::size_t>(i)] =
          model.optics.system(std::abs(static_cast<double>(i - 1) * cache.otf_node_step));
  });
}

// FFTW executes a plan on another array only at the alignment it was planned
// for; every row and column block here starts on a 16-byte boundary.
void check_alignment(const void* p) {
  if (fftw_alignment_of(static_cast<double*>(const_cast<void*>(p))) != 0)
    throw Error(Status::internal, "convolution: a transform row is not aligned for FFTW");
}

// Step 1 on one row of the buffer: filled from its source row of w samples,
// the ends repeated, and transformed in place; a constant row gets its
// closed-form spectrum (the DFT of n values v: n v at zero frequency).
// Returns whether it was constant.
bool transform_row(const double* source, int w, int pad, int cols, std::size_t stride, double* row,
                   fftw_plan& forward) {
  const bool constant = std::all_of(source + 1, source + w, [v = source[0]](double x) { return x == v; });
  if (constant) {
    std::fill(row, row + stride, 0.0);
    row[0] = source[0] * cols;
    return true;
  }
  std::fill(row, row + pad, source[0]);
  std::copy(source, source + w, row + pad);
  std::fill(row + pad + w, row + cols, source[w - 1]);
  if (!forward) forward = fftw::row_r2c(cols);
  check_alignment(row);
  fftw_execute_dft_r2c(forward, row, reinterpret_cast<fftw_complex*>(row));
  return false;
}

// Whether all rows a thread transformed were constant, and at which value,
// to find a uniform scene.
struct Constancy {
  bool seen = false, constant = true;
  double value = 0;
  void add(double first_value, bool row_constant) {
    if (!seen) value = first_value;
    seen = true;
    constant = constant && row_constant && first_value == value;
  }
};
bool uniform(const std::vector<Constancy>& constancy, double first) {
  return std::all_of(constancy.begin(), constancy.end(),
                     [first](const Constancy& c) { return !c.seen || (c.constant && c.value == first); });
}

// Step 2 on `count` adjacent columns of the row transforms, `stride` complex
// values from row to row (transformed in place): times the scaled OTF
// (otf(r, j) of row r and the block's column j, zero on rows where
// zero_row(r)) and the pixel rows' box-sum phases, folded onto the
// pixel-row frequencies and transformed back into block_spectrum
// (pixel_rows x count).
template <class Otf, class ZeroRow>
void fold_columns(const SceneConvolutionCache& cache, int pixel_rows, fftw_complex* columns, int count, int stride,
                  fftw_plan forward, fftw_plan backward, fftw_complex* block_spectrum, const Otf& otf,
                  const ZeroRow& zero_row) {
  const int rows = cache.fft_rows;
  check_alignment(columns);
  fftw_execute_dft(forward, columns, columns);
  std::fill_n(&block_spectrum[0][0], 2 * static_cast<std::size_t>(pixel_rows) * count, 0.0);
  for (int r = 0; r < rows; ++r) {
    if (zero_row(r)) continue;
    const Complex phase = cache.row_phases[static_cast<std::size_t>(r)];
    const std::size_t i0 = static_cast<std::size_t>(r) * static_cast<std::size_t>(stride);
    const std::size_t o0 = static_cast<std::size_t>(r % pixel_rows) * count;
    for (int j = 0; j < count; ++j) {  // written out: std::complex's product checks for NaNs
      const double gain = otf(r, j);
      const double re = gain * phase.real(), im = gain * phase.imag();
      const double* y = columns[i0 + j];
      double* z = block_spectrum[o0 + j];
      z[0] += y[0] * re - y[1] * im;
      z[1] += y[0] * im + y[1] * re;
    }
  }
  fftw_execute_dft(backward, block_spectrum, block_spectrum);
}

// Step 3 on one pixel row's spectrum (its first `passband` columns of the
// half spectrum): weighted by the pixel columns' box-sum phases, folded onto
// the cols / k pixel-column frequencies (the columns past cols / 2 are the
// conjugates of those below it; past the passband, zero) and transformed
// back: nx pixel means.
void pixel_row(const SceneConvolutionCache& cache, const fftw_complex* spectrum_row, int passband, int pixel_cols,
               fftw_plan backward, fftw_complex* row, std::int64_t nx, double* out) {
  const int cols = cache.fft_cols, pixel_half = pixel_cols / 2 + 1;
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
  std::copy_n(samples, nx, out);
}

}  // namespace

std::vector<double> pixel_radiance(const SensorModel& model, const radiometry::RadianceImage& scene,
                                   unsigned threads, std::vector<double> storage) {
  SceneConvolutionCache& cache = *model.scene_convolution;
  const geometry::SampleGrid& g = scene.grid;
  std::call_once(cache.shape_built, [&] { build_shape(cache, model, g); });
  std::call_once(cache.built, [&] { build_whole(cache, model, g, threads); });
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
  // (constant rows cost next to nothing).
  std::vector<Constancy> constancy(parallel_range_count(rows, threads, row_chunk));
  parallel_chunks(rows, threads, row_chunk, [&](unsigned t, std::int64_t r0, std::int64_t r1) {
    fftw_plan forward = nullptr;  // asked for on the chunk's first row that needs it
    for (auto r = static_cast<int>(r0); r < r1; ++r) {
      const int source_row = std::clamp(r - pad, 0, h - 1);
      double* row = real + static_cast<std::size_t>(r) * stride;
      if (r > r0 && source_row == std::clamp(r - 1 - pad, 0, h - 1)) {  // padding: the row above again
        std::memcpy(row, row - stride, stride * sizeof(double));
        continue;
      }
      const double* source = radiance.data() + static_cast<std::size_t>(source_row) * w;
      constancy[t].add(source[0], transform_row(source, w, pad, cols, stride, row, forward));
    }
  });
  if (uniform(constancy, radiance.front())) {
    std::fill(out.begin(), out.end(), radiance.front());
    return out;
  }

  // Step 2: each block of passband columns (fold_columns): the spectrum of
  // the field's pixel rows (sums over their k sample rows), kept for step 3.
  // Each thread takes a contiguous range of blocks (neighbouring blocks share
  // cache lines).
  fftw_complex* folded = cache.folded.get();
  parallel_ranges(passband, threads, [&](std::int64_t c0, std::int64_t c1) {
    const fftw_plan plans[2] = {fftw::columns(rows, column_block, half, FFTW_FORWARD),
                                fftw::columns(pixel_rows, column_block, column_block, FFTW_BACKWARD)};
    fftw::ComplexBuffer block_buffer = fftw::complex_buffer(static_cast<std::size_t>(pixel_rows) * column_block);
    fftw_complex* block_spectrum = block_buffer.get();
    for (auto block = static_cast<int>(c0); block < c1; block += column_block) {
      const int count = std::min(column_block, static_cast<int>(c1) - block);
      const bool whole = count == column_block;
      const double* otf = cache.otf_scaled.data() + block;
      fold_columns(cache, pixel_rows, spectrum + block, count, half,
                   whole ? plans[0] : fftw::columns(rows, count, half, FFTW_FORWARD),
                   whole ? plans[1] : fftw::columns(pixel_rows, count, count, FFTW_BACKWARD), block_spectrum,
                   [otf, half](int r, int j) { return otf[static_cast<std::size_t>(r) * half + j]; },
                   [](int) { return false; });
      for (std::int64_t m = 0; m < ny; ++m)
        std::memcpy(&folded[static_cast<std::size_t>(m) * half + static_cast<std::size_t>(block)],
                    &block_spectrum[static_cast<std::size_t>(m) * count], sizeof(fftw_complex) * count);
    }
  }, column_block);

  // Step 3: each pixel row (pixel_row): the pixel means.
  const int pixel_half = pixel_cols / 2 + 1;
  const fftw_plan backward = fftw::row_c2r(pixel_cols);
  std::vector<fftw::ComplexBuffer> row_buffers(parallel_range_count(ny, threads, pixel_row_chunk));  // one a thread
  parallel_chunks(ny, threads, pixel_row_chunk, [&](unsigned t, std::int64_t m0, std::int64_t m1) {
    if (!row_buffers[t]) row_buffers[t] = fftw::complex_buffer(static_cast<std::size_t>(pixel_half));
    for (std::int64_t m = m0; m < m1; ++m)
      pixel_row(cache, folded + static_cast<std::size_t>(m) * half, passband, pixel_cols, backward,
                row_buffers[t].get(), nx, out.data() + m * nx);
  });
  return out;
}

std::int64_t whole_frame_bytes(const SensorModel& model) {
  const geometry::SampleGrid& g = model.grid;
  const TransformShape t = transform_shape(model, g);
  // per sample: radiance and hit (16 bytes) and the scene display's byte;
  // per transform cell of the half spectrum: a complex value and the OTF;
  // per pixel row: its folded half spectrum
  const std::int64_t half = t.cols / 2 + 1;
  return 17 * g.width() * g.height() + 24 * static_cast<std::int64_t>(t.rows) * half + 16 * g.pixels_y * half;
}

std::vector<double> pixel_radiance_in_strips(const SensorModel& model, const geometry::SampleGrid& g,
                                             const SceneRowSource& scene_rows, unsigned threads,
                                             std::vector<double> storage) {
  SceneConvolutionCache& cache = *model.scene_convolution;
  std::call_once(cache.shape_built, [&] { build_shape(cache, model, g); });
  std::call_once(cache.strips_built, [&] { build_strips(cache, model, g, threads); });
  if (g.width() != cache.grid_cols || g.height() != cache.grid_rows)
    throw Error(Status::internal, "convolution: the scene's sample grid is not the sensor model's");
  const std::int64_t nx = g.pixels_x, ny = g.pixels_y, k = g.per_pixel;
  std::vector<double> out = std::move(storage);
  out.resize(static_cast<std::size_t>(nx * ny));
  const int w = static_cast<int>(g.width()), h = static_cast<int>(g.height());
  const int rows = cache.fft_rows, cols = cache.fft_cols, half = cols / 2 + 1, pad = cache.pad;
  const int pixel_rows = rows / static_cast<int>(k), pixel_cols = cols / static_cast<int>(k);
  const int passband = cache.strip_passband_cols;
  const std::size_t stride = 2 * static_cast<std::size_t>(half);
  // The row transforms' passband columns and the folded pixel rows go to a
  // temporary file in groups of kGroup columns, each group's rows together:
  // group g of the transforms at g rows kGroup, of the folded rows after them.
  constexpr int kGroup = 64;
  const int groups = std::max(1, (passband + kGroup - 1) / kGroup);
  const std::uint64_t cell = sizeof(fftw_complex);
  const std::uint64_t transform_group = static_cast<std::uint64_t>(rows) * kGroup * cell;
  const std::uint64_t folded_group = static_cast<std::uint64_t>(ny) * kGroup * cell;
  const ScratchFile file(groups * (transform_group + folded_group), "scene convolution in strips");
  // Strips of rows: about kStripBytes of row transforms (and as much scene).
  constexpr std::uint64_t kStripBytes = 64ull << 20;
  const int strip_rows = static_cast<int>(std::clamp<std::uint64_t>(kStripBytes / (stride * sizeof(double)), 16, 4096));

  // Step 1: strips of the buffer's rows from strips of the scene's, each
  // row transformed (transform_row), each group of the strip written at once.
  std::vector<Constancy> constancy;
  double first_sample = 0;
  {
    fftw::RealBuffer strip = fftw::real_buffer(static_cast<std::size_t>(strip_rows) * stride);
    std::vector<fftw::ComplexBuffer> gathers(
        static_cast<std::size_t>(std::max(1u, parallel_range_count(groups, threads, 1))));
    for (int s0 = 0; s0 < rows; s0 += strip_rows) {
      const int s1 = std::min(rows, s0 + strip_rows);
      const int a = std::clamp(s0 - pad, 0, h - 1), b = std::clamp(s1 - 1 - pad, 0, h - 1) + 1;
      const double* source_rows = scene_rows(a, b);
      if (s0 == 0) first_sample = source_rows[0];
      std::vector<Constancy> mine(parallel_range_count(s1 - s0, threads, row_chunk));
      parallel_chunks(s1 - s0, threads, row_chunk, [&](unsigned t, std::int64_t i0, std::int64_t i1) {
        fftw_plan forward = nullptr;
        for (auto i = static_cast<int>(i0); i < i1; ++i) {
          const int r = s0 + i, source_row = std::clamp(r - pad, 0, h - 1);
          double* row = strip.get() + static_cast<std::size_t>(i) * stride;
          if (i > i0 && source_row == std::clamp(r - 1 - pad, 0, h - 1)) {
            std::memcpy(row, row - stride, stride * sizeof(double));
            continue;
          }
          const double* source = source_rows + static_cast<std::size_t>(source_row - a) * w;
          mine[t].add(source[0], transform_row(source, w, pad, cols, stride, row, forward));
        }
      });
      constancy.insert(constancy.end(), mine.begin(), mine.end());
      const auto* spectrum = reinterpret_cast<const fftw_complex*>(strip.get());
      parallel_indexed_ranges(groups, threads, [&](unsigned t, std::int64_t g0, std::int64_t g1) {
        const std::size_t n = static_cast<std::size_t>(s1 - s0) * kGroup;
        if (!gathers[t]) gathers[t] = fftw::complex_buffer(static_cast<std::size_t>(strip_rows) * kGroup);
        fftw_complex* gather = gathers[t].get();
        for (std::int64_t q = g0; q < g1; ++q) {
          const int c0 = static_cast<int>(q) * kGroup, count = std::min(kGroup, half - c0);
          for (int i = 0; i < s1 - s0; ++i)
            std::memcpy(gather[static_cast<std::size_t>(i) * kGroup], spectrum[static_cast<std::size_t>(i) * half + c0],
                        cell * static_cast<std::size_t>(count));
          file.write(static_cast<std::uint64_t>(q) * transform_group + static_cast<std::uint64_t>(s0) * kGroup * cell,
                     gather, n * cell);
        }
      }, 1);
    }
  }
  if (uniform(constancy, first_sample)) {
    std::fill(out.begin(), out.end(), first_sample);
    return out;
  }

  // Step 2: each group read back, its blocks folded (fold_columns) with the
  // OTF's cubic in |f|, the group's folded pixel rows written back.
  const double dx = g.pitch_x_cm / static_cast<double>(k), dy = g.pitch_y_cm / static_cast<double>(k);
  const double scale = 1.0 / (static_cast<double>(rows) * static_cast<double>(cols));
  const double cutoff2 = cache.otf_cutoff_cycles_per_cm * cache.otf_cutoff_cycles_per_cm;
  std::vector<double> fy2(static_cast<std::size_t>(rows));
  for (int r = 0; r < rows; ++r) fy2[static_cast<std::size_t>(r)] = std::pow(frequency(r, rows, dy), 2);
  const double* nodes = cache.otf_radial.data();
  const double node_step = cache.otf_node_step;
  const auto otf_of = [&](double f2) {
    const double u = std::sqrt(f2) / node_step;
    const auto i = static_cast<std::size_t>(u);
    if (i >= static_cast<std::size_t>(kStripOtfNodes) + 1) return 0.0;
    double weight[4];
    catmull_rom_weights(u - static_cast<double>(i), weight);
    const double* n = nodes + i;  // node i - 1
    return (weight[0] * n[0] + weight[1] * n[1] + weight[2] * n[2] + weight[3] * n[3]) * scale;
  };
  parallel_ranges(groups, threads, [&](std::int64_t g0, std::int64_t g1) {
    const fftw_plan plans[2] = {fftw::columns(rows, column_block, kGroup, FFTW_FORWARD),
                                fftw::columns(pixel_rows, column_block, column_block, FFTW_BACKWARD)};
    fftw::ComplexBuffer group_buffer = fftw::complex_buffer(static_cast<std::size_t>(rows) * kGroup);
    fftw::ComplexBuffer folded_buffer = fftw::complex_buffer(static_cast<std::size_t>(ny) * kGroup);
    fftw::ComplexBuffer block_buffer = fftw::complex_buffer(static_cast<std::size_t>(pixel_rows) * column_block);
    std::vector<double> otf_block(static_cast<std::size_t>(rows) * column_block);
    for (std::int64_t q = g0; q < g1; ++q) {
      const int c0 = static_cast<int>(q) * kGroup, width = std::min(kGroup, passband - c0);
      file.read(static_cast<std::uint64_t>(q) * transform_group, group_buffer.get(), transform_group);
      for (int block = 0; block < width; block += column_block) {
        const int count = std::min(column_block, width - block);
        const bool whole = count == column_block;
        for (int r = 0; r < rows; ++r)
          for (int j = 0; j < count; ++j) {
            const double fx = static_cast<double>(c0 + block + j) / (cols * dx);
            otf_block[static_cast<std::size_t>(r) * column_block + static_cast<std::size_t>(j)] =
                fy2[static_cast<std::size_t>(r)] >= cutoff2 ? 0.0 : otf_of(fx * fx + fy2[static_cast<std::size_t>(r)]);
          }
        fold_columns(cache, pixel_rows, group_buffer.get() + block, count, kGroup,
                     whole ? plans[0] : fftw::columns(rows, count, kGroup, FFTW_FORWARD),
                     whole ? plans[1] : fftw::columns(pixel_rows, count, count, FFTW_BACKWARD), block_buffer.get(),
                     [&](int r, int j) {
                       return otf_block[static_cast<std::size_t>(r) * column_block + static_cast<std::size_t>(j)];
                     },
                     [&](int r) { return fy2[static_cast<std::size_t>(r)] >= cutoff2; });
        for (std::int64_t m = 0; m < ny; ++m)
          std::memcpy(folded_buffer[static_cast<std::size_t>(m) * kGroup + static_cast<std::size_t>(block)],
                      block_buffer[static_cast<std::size_t>(m) * count], cell * static_cast<std::size_t>(count));
      }
      file.write(groups * transform_group + static_cast<std::uint64_t>(q) * folded_group, folded_buffer.get(),
                 folded_group);
    }
  }, 1);

  // Step 3: strips of pixel rows gathered from the groups, each row made
  // into pixel means (pixel_row).
  const int pixel_half = pixel_cols / 2 + 1;
  const fftw_plan backward = fftw::row_c2r(pixel_cols);
  const std::size_t spectrum_stride = static_cast<std::size_t>(groups) * kGroup;
  const int strip_pixel_rows = static_cast<int>(
      std::min<std::uint64_t>(static_cast<std::uint64_t>(ny),
                              std::max<std::uint64_t>(4, kStripBytes / (spectrum_stride * cell))));
  fftw::ComplexBuffer strip = fftw::complex_buffer(static_cast<std::size_t>(strip_pixel_rows) * spectrum_stride);
  fftw::ComplexBuffer gather = fftw::complex_buffer(static_cast<std::size_t>(strip_pixel_rows) * kGroup);
  std::vector<fftw::ComplexBuffer> row_buffers(parallel_range_count(ny, threads, pixel_row_chunk));
  for (std::int64_t m0 = 0; m0 < ny; m0 += strip_pixel_rows) {
    const std::int64_t m1 = std::min<std::int64_t>(ny, m0 + strip_pixel_rows);
    for (int q = 0; q < groups; ++q) {
      file.read(groups * transform_group + static_cast<std::uint64_t>(q) * folded_group +
                    static_cast<std::uint64_t>(m0) * kGroup * cell,
                gather.get(), static_cast<std::size_t>(m1 - m0) * kGroup * cell);
      for (std::int64_t m = m0; m < m1; ++m)
        std::memcpy(strip[static_cast<std::size_t>(m - m0) * spectrum_stride + static_cast<std::size_t>(q) * kGroup],
                    gather[static_cast<std::size_t>(m - m0) * kGroup], kGroup * cell);
    }
    parallel_chunks(m1 - m0, threads, pixel_row_chunk, [&](unsigned t, std::int64_t i0, std::int64_t i1) {
      if (!row_buffers[t]) row_buffers[t] = fftw::complex_buffer(static_cast<std::size_t>(pixel_half));
      for (std::int64_t i = i0; i < i1; ++i)
        pixel_row(cache, strip.get() + static_cast<std::size_t>(i) * spectrum_stride, passband, pixel_cols, backward,
                  row_buffers[t].get(), nx, out.data() + (m0 + i) * nx);
    });
  }
  return out;
}

}  // namespace eoir::sensor
