#include "sensor/scene_convolution.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel_ranges.hpp"
#include "sensor/sensor_model.hpp"

namespace eoir::sensor {
namespace {

// FFT frequency (cycles per unit of the spacing) of index i on n points.
double frequency(int i, int n, double spacing) {
  const int k = i <= n / 2 ? i : i - n;
  return static_cast<double>(k) / (static_cast<double>(n) * spacing);
}

void build(SceneConvolutionCache& cache, const SensorModel& model, const geometry::SampleGrid& g, unsigned threads) {
  cache.grid_cols = g.width();
  cache.grid_rows = g.height();
  const int w = static_cast<int>(g.width()), h = static_cast<int>(g.height());
  cache.pad = static_cast<int>(std::lround(model.fidelity().fft_padding * static_cast<double>(g.guard_samples())));
  cache.fft_cols = fftw::good_size(w + 2 * cache.pad);
  cache.fft_rows = fftw::good_size(h + 2 * cache.pad);
  const int rows = cache.fft_rows, cols = cache.fft_cols, half = cols / 2 + 1;
  const double k = static_cast<double>(g.per_pixel);
  const double dx = g.pitch_x_cm / k, dy = g.pitch_y_cm / k;
  const double scale = 1.0 / (static_cast<double>(rows) * static_cast<double>(cols));
  cache.otf_scaled.resize(static_cast<std::size_t>(rows) * static_cast<std::size_t>(half));
  parallel_ranges(rows, threads, [&](std::int64_t r0, std::int64_t r1) {
    for (auto r = static_cast<int>(r0); r < r1; ++r) {
      const double fy = frequency(r, rows, dy);
      for (int c = 0; c < half; ++c) {
        const double fx = static_cast<double>(c) / (cols * dx);
        cache.otf_scaled[static_cast<std::size_t>(r) * half + c] = model.optics.system(std::sqrt(fx * fx + fy * fy)) * scale;
      }
    }
  }, 16);
  cache.buffer = fftw::complex_buffer(static_cast<std::size_t>(rows) * static_cast<std::size_t>(half));
}

}  // namespace

BlurredScene convolve_scene(const SensorModel& model, const radiometry::RadianceImage& scene, unsigned threads) {
  SceneConvolutionCache& cache = *model.scene_convolution;
  const geometry::SampleGrid& g = scene.grid;
  std::call_once(cache.built, [&] { build(cache, model, g, threads); });
  if (g.width() != cache.grid_cols || g.height() != cache.grid_rows)
    throw Error(Status::internal, "convolution: the scene's sample grid is not the sensor model's");
  std::unique_lock<std::mutex> lock(cache.buffer_mutex);
  const int w = static_cast<int>(g.width()), h = static_cast<int>(g.height());
  const int rows = cache.fft_rows, cols = cache.fft_cols, half = cols / 2 + 1, pad = cache.pad;
  const std::size_t stride = 2 * static_cast<std::size_t>(half);  // reals per row in place
  fftw_complex* spectrum = cache.buffer.get();
  double* real = reinterpret_cast<double*>(spectrum);
  const std::vector<double>& radiance = scene.radiance_W_cm2_sr;
  parallel_ranges(rows, threads, [&](std::int64_t r0, std::int64_t r1) {
    for (auto r = static_cast<int>(r0); r < r1; ++r) {
      const double* source = radiance.data() + static_cast<std::size_t>(std::clamp(r - pad, 0, h - 1)) * w;
      double* row = real + static_cast<std::size_t>(r) * stride;
      std::fill(row, row + pad, source[0]);
      std::copy(source, source + w, row + pad);
      std::fill(row + pad + w, row + cols, source[w - 1]);
    }
  }, 16);
  fftw_execute_dft_r2c(fftw::r2c_2d(rows, cols, fftw::Placement::in_place, threads), real, spectrum);
  parallel_ranges(rows, threads, [&](std::int64_t r0, std::int64_t r1) {
    const std::size_t begin = static_cast<std::size_t>(r0) * half, end = static_cast<std::size_t>(r1) * half;
    for (std::size_t i = begin; i < end; ++i) {
      spectrum[i][0] *= cache.otf_scaled[i];
      spectrum[i][1] *= cache.otf_scaled[i];
    }
  }, 16);
  fftw_execute_dft_c2r(fftw::c2r_2d(rows, cols, fftw::Placement::in_place, threads), spectrum, real);
  return BlurredScene(std::move(lock), real, stride, pad);
}

}  // namespace eoir::sensor
