// The scene convolved with the system PSF (eq. 49's L conv PSF): the sample
// grid, guard band included, is transformed by FFT, multiplied by OTF_system
// (eq. 39) on the image-space frequency grid of the samples and transformed
// back. Around the guard band the FFT buffer is padded by fft_padding guard
// bands with the border samples repeated, so the circular wrap of the
// transform mixes only padding that lies two PSF reaches from the field.
//
// The transform size, the OTF on its frequency grid and the transform buffer
// depend only on the sensor model: the first frame makes them and the model
// keeps them (SensorModel::scene_convolution), so later frames evaluate no
// OTF and touch no fresh memory (DESIGN.md 4).
#pragma once
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

#include "core/fftw_plans.hpp"
#include "radiometry/radiance_image.hpp"

namespace eoir::sensor {

struct SensorModel;

struct SceneConvolutionCache {
  std::once_flag built;
  std::int64_t grid_cols = 0, grid_rows = 0;  // the sample grid it was made for
  int fft_cols = 0, fft_rows = 0;  // transform size (FFTW-friendly)
  int pad = 0;                      // samples of padding on each side of the grid
  // OTF_system(|f|) / (cols rows) on the transform's half-spectrum grid,
  // rows x (cols / 2 + 1), the FFT normalisation folded in.
  std::vector<double> otf_scaled;
  // In-place transform buffer: rows x (cols / 2 + 1) complex values, read as
  // rows of 2 (cols / 2 + 1) reals. One frame at a time holds it.
  std::mutex buffer_mutex;
  fftw::ComplexBuffer buffer;
};

// The convolved sample grid, read in place; holds the model's transform
// buffer until it is destroyed.
class BlurredScene {
 public:
  BlurredScene(std::unique_lock<std::mutex> lock, const double* values, std::size_t row_stride, int pad)
      : lock_(std::move(lock)), values_(values), row_stride_(row_stride), pad_(pad) {}
  // The sample at (row, col) of the grid (guard band included).
  double at(std::int64_t row, std::int64_t col) const {
    return values_[static_cast<std::size_t>(row + pad_) * row_stride_ + static_cast<std::size_t>(col + pad_)];
  }

 private:
  std::unique_lock<std::mutex> lock_;
  const double* values_;
  std::size_t row_stride_;
  int pad_;
};

// threads: 0 = all cores; the result depends on them only through the
// rounding of FFTW's plan for that thread count.
BlurredScene convolve_scene(const SensorModel& model, const radiometry::RadianceImage& scene, unsigned threads);

}  // namespace eoir::sensor
