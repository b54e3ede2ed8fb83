// Eq. 49 (the scene convolved with the system PSF and averaged over each
// pixel) by the engine's folded row/column transform
// (sensor/scene_convolution.hpp) against the same equation done directly: the
// padded sample grid through a full 2-D FFT, times OTF_system (eq. 39) at
// every frequency, back, and the mean of each pixel's k x k samples. The fold
// is an identity (the box sum's spectrum aliased onto the pixel grid), so the
// two agree to rounding: 1e-12 of the largest pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "sensor/image_chain.hpp"

using namespace eoir::sensor;

namespace {

// Direct eq. 49 on the transform size and padding the model chose.
std::vector<double> direct_pixel_radiance(const SensorModel& model, const eoir::radiometry::RadianceImage& scene) {
  const SceneConvolutionCache& cache = *model.scene_convolution;
  const auto& g = scene.grid;
  const int rows = cache.fft_rows, cols = cache.fft_cols, half = cols / 2 + 1, pad = cache.pad;
  const int w = static_cast<int>(g.width()), h = static_cast<int>(g.height()), k = static_cast<int>(g.per_pixel);
  eoir::fftw::RealBuffer real = eoir::fftw::real_buffer(static_cast<std::size_t>(rows) * cols);
  eoir::fftw::ComplexBuffer spectrum = eoir::fftw::complex_buffer(static_cast<std::size_t>(rows) * half);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      real[static_cast<std::size_t>(r) * cols + c] =
          scene.radiance_W_cm2_sr[static_cast<std::size_t>(std::clamp(r - pad, 0, h - 1)) * w +
                                  static_cast<std::size_t>(std::clamp(c - pad, 0, w - 1))];
  fftw_plan forward = fftw_plan_dft_r2c_2d(rows, cols, real.get(), spectrum.get(), FFTW_ESTIMATE);
  fftw_plan backward = fftw_plan_dft_c2r_2d(rows, cols, spectrum.get(), real.get(), FFTW_ESTIMATE);
  fftw_execute(forward);
  const double dx = g.pitch_x_cm / k, dy = g.pitch_y_cm / k;
  for (int r = 0; r < rows; ++r) {
    const double fy = (r <= rows / 2 ? r : r - rows) / (rows * dy);
    for (int c = 0; c < half; ++c) {
      const double fx = c / (cols * dx);
      const double gain = model.optics.system(std::hypot(fx, fy)) / (static_cast<double>(rows) * cols);
      spectrum[static_cast<std::size_t>(r) * half + c][0] *= gain;
      spectrum[static_cast<std::size_t>(r) * half + c][1] *= gain;
    }
  }
  fftw_execute(backward);
  fftw_destroy_plan(forward);
  fftw_destroy_plan(backward);
  std::vector<double> out(static_cast<std::size_t>(g.pixels_x * g.pixels_y), 0.0);
  const std::int64_t first = pad + g.guard_samples();
  for (std::int64_t m = 0; m < g.pixels_y; ++m)
    for (std::int64_t n = 0; n < g.pixels_x; ++n) {
      double sum = 0;
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j)
          sum += real[static_cast<std::size_t>(first + m * k + i) * cols + static_cast<std::size_t>(first + n * k + j)];
      out[static_cast<std::size_t>(m * g.pixels_x + n)] = sum / (k * k);
    }
  return out;
}

// Noise, a bright block and constant rows (dark sky, whose row transform is
// the closed form).
eoir::radiometry::RadianceImage test_scene(const SensorModel& model, unsigned seed) {
  eoir::radiometry::RadianceImage scene;
  scene.grid = model.grid;
  const std::int64_t w = model.grid.width(), h = model.grid.height();
  scene.radiance_W_cm2_sr.assign(static_cast<std::size_t>(w * h), 2e-5);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1e-4);
  for (std::int64_t r = h / 5; r < h - h / 3; ++r)
    for (std::int64_t c = 0; c < w; ++c)
      scene.radiance_W_cm2_sr[static_cast<std::size_t>(r * w + c)] = u(rng) + (std::abs(c - w / 2) < w / 6 ? 1e-3 : 0.0);
  return scene;
}

struct Case {
  const char* name;
  std::int64_t pixels_x, pixels_y, samples_per_pixel;
  double fft_padding, f_number, wavelength_um;
};

TEST(Spec_5_11_SceneConvolution, FoldedTransformEqualsTheDirectOne) {
  const Case cases[] = {
      {"Table 3", 128, 128, 4, 1.0, 3.5, 2.5},
      {"odd field, 3 samples", 37, 23, 3, 1.0, 3.5, 2.5},
      {"1 sample, half padding", 40, 31, 1, 0.5, 3.5, 2.5},
      {"2 samples, no padding", 33, 48, 2, 0.0, 3.5, 2.5},
      {"cutoff inside the sample grid", 32, 24, 4, 1.0, 40.0, 100.0},
  };
  for (const Case& c : cases) {
    SensorParameters p;
    p.noise_enabled = false;
    p.horizontal_pixels = c.pixels_x;
    p.vertical_pixels = c.pixels_y;
    p.fidelity.samples_per_pixel = c.samples_per_pixel;
    p.fidelity.fft_padding = c.fft_padding;
    p.f_number = c.f_number;
    p.diffraction_wavelength_um = c.wavelength_um;
    const auto model = resolve_sensor(p);
    const auto scene = test_scene(*model, 7);
    const std::vector<double> folded = pixel_radiance(*model, scene, 1);
    const std::vector<double> direct = direct_pixel_radiance(*model, scene);
    const std::vector<double> two_threads = pixel_radiance(*model, scene, 2);
    const double largest = *std::max_element(direct.begin(), direct.end());
    double worst = 0, worst_threads = 0;
    for (std::size_t i = 0; i < direct.size(); ++i) {
      worst = std::max(worst, std::abs(folded[i] - direct[i]) / largest);
      worst_threads = std::max(worst_threads, std::abs(two_threads[i] - folded[i]) / largest);
    }
    EXPECT_LT(worst, 1e-12) << c.name;
    EXPECT_LT(worst_threads, 1e-13) << c.name;
    const SceneConvolutionCache& cache = *model->scene_convolution;
    EXPECT_EQ(cache.fft_rows % c.samples_per_pixel, 0) << c.name;
    EXPECT_EQ(cache.fft_cols % c.samples_per_pixel, 0) << c.name;
    if (std::string(c.name) == "cutoff inside the sample grid") {  // the pruned columns are exercised
      EXPECT_LT(cache.passband_cols, cache.fft_cols / 2 + 1) << c.name;
    }
  }
}

// A uniform scene stays uniform, exactly (OTF(0) = 1, the padding repeats the
// border): returned untransformed.
TEST(Spec_5_11_SceneConvolution, UniformSceneIsReturnedAsIs) {
  SensorParameters p;
  p.noise_enabled = false;
  const auto model = resolve_sensor(p);
  eoir::radiometry::RadianceImage scene;
  scene.grid = model->grid;
  scene.radiance_W_cm2_sr.assign(static_cast<std::size_t>(model->grid.width() * model->grid.height()), 3.25e-6);
  for (double v : pixel_radiance(*model, scene, 2)) ASSERT_EQ(v, 3.25e-6);
  // Constant rows at two values are not uniform: the transform runs, every
  // row by the closed form.
  for (std::size_t i = 0; i < scene.radiance_W_cm2_sr.size() / 2; ++i) scene.radiance_W_cm2_sr[i] = 1e-6;
  const std::vector<double> split = pixel_radiance(*model, scene, 2);
  const std::vector<double> direct = direct_pixel_radiance(*model, scene);
  for (std::size_t i = 0; i < direct.size(); ++i) ASSERT_NEAR(split[i], direct[i], 1e-12 * 3.25e-6) << i;
  EXPECT_NE(split.front(), split.back());
}

}  // namespace
