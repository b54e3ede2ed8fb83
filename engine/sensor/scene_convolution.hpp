// Eq. 49's (1/A_d) integral over the pixel of L conv PSF: the sample grid,
// guard band included, is transformed by FFT, multiplied by OTF_system
// (eq. 39) on the image-space frequency grid of the samples, transformed back
// and averaged over each pixel's samples. Around the guard band the FFT
// buffer is padded by fft_padding guard bands with the border samples
// repeated, so the circular wrap of the transform mixes only padding that
// lies two PSF reaches from the field.
//
// The 2-D transform is done as rows, then columns, each thread taking its own
// rows or columns, so every step runs on all threads and in cache:
//  1. each row of the buffer is filled from the scene and transformed at once
//     (a constant row, such as dark sky, has the closed-form spectrum
//     [n v, 0, ...]);
//  2. each block of columns is transformed, multiplied by the OTF and folded:
//     the mean over a pixel's k samples is a box sum, which multiplies the
//     spectrum by Phi(f) = sum_j exp(2 pi i f (o + j)), and keeping every k-th
//     sum aliases the n frequencies onto n / k (the transform's period holds
//     whole pixels); the n / k are transformed back while in cache. Columns
//     where the OTF is zero (beyond the diffraction cutoff, eq. 34) are left
//     out;
//  3. each pixel row is folded the same way along the row and transformed
//     back at n / k points: the pixel means.
// The inverse transforms thus run on the pixel grid, k^2 times smaller than
// the sample grid; the result equals a full 2-D transform's averaged over the
// pixels, up to rounding.
//
// The transform size, the OTF on its frequency grid and the transform buffer
// depend only on the sensor model: the first frame makes them and the model
// keeps them (SensorModel::scene_convolution), so later frames evaluate no
// OTF and touch no fresh memory (DESIGN.md 4).
#pragma once
#include <cstddef>
#include <complex>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include "core/fftw_plans.hpp"
#include "radiometry/radiance_image.hpp"

namespace eoir::sensor {

struct SensorModel;

struct SceneConvolutionCache {
  std::once_flag shape_built, built, strips_built;
  std::int64_t grid_cols = 0, grid_rows = 0;  // the sample grid it was made for
  int fft_cols = 0, fft_rows = 0;  // transform size: k times an FFTW-friendly size
  int pad = 0;                      // samples of padding on each side of the grid
  // OTF_system(|f|) / (cols rows) on the transform's half-spectrum grid,
  // rows x (cols / 2 + 1), the FFT normalisation folded in.
  std::vector<double> otf_scaled;
  int passband_cols = 0;  // half-spectrum columns from here on have a zero OTF
  // Box-sum phases Phi of the field's pixels along the rows (divided by k^2,
  // for the mean) and the columns, one per transform frequency.
  std::vector<std::complex<double>> row_phases, column_phases;
  // In-place transform buffer: rows x (cols / 2 + 1) complex values, read as
  // rows of 2 (cols / 2 + 1) reals. One frame at a time holds it.
  std::mutex buffer_mutex;
  fftw::ComplexBuffer buffer;
  // The field's pixel rows, each's half spectrum (cols / 2 + 1) after step 2.
  fftw::ComplexBuffer folded;
  // Strips (pixel_radiance_in_strips): the OTF against |f| (cycles/cm) at
  // nodes (i - 1) otf_node_step, a cubic between them, and the passband.
  std::vector<double> otf_radial;
  double otf_node_step = 0, otf_cutoff_cycles_per_cm = 0;
  int strip_passband_cols = 0;
};

// Eq. 49 without the responsivity: pixel-mean radiance of the convolved scene (W cm^-2 sr^-1, pixels_x x
// pixels_y, row-major). threads: 0 = all cores; the result does not depend on
// them beyond rounding. A uniform scene (no extended source, black or lit by
// the background light alone) stays uniform (the OTF is 1 at zero frequency
// and the padding repeats the border): it is returned without a transform.
// `storage`: a buffer the result reuses.
std::vector<double> pixel_radiance(const SensorModel& model, const radiometry::RadianceImage& scene,
                                   unsigned threads, std::vector<double> storage = {});

// The memory (bytes) pixel_radiance and the whole frame's scene hold: the
// sample buffers and the transform's.
std::int64_t whole_frame_bytes(const SensorModel& model);

// Rows [first, last) of the sample grid (radiance, row-major), valid until
// the next call; called with increasing rows.
using SceneRowSource = std::function<const double*(std::int64_t first, std::int64_t last)>;

// The same pixel means with the scene in strips of rows, for frames too
// large for memory (fidelity scene_memory_max_mib): each strip's rows are
// transformed as step 1 does and written, by groups of passband columns, to
// a temporary file (core/scratch_file.hpp); each group is read back for
// step 2 and its folded pixel rows written back; step 3 reads strips of
// pixel rows. Memory is a few strips, the OTF's cubic in |f| (kStripOtfNodes
// nodes to the cutoff, within 1e-12 of eq. 39) and the result; equal to
// pixel_radiance to 1e-9 relative (rounding and the cubic).
std::vector<double> pixel_radiance_in_strips(const SensorModel& model, const geometry::SampleGrid& grid,
                                             const SceneRowSource& scene_rows, unsigned threads,
                                             std::vector<double> storage = {});

}  // namespace eoir::sensor
