// Point sources on the detector at the cost of a table look-up (spec 5.11.2,
// eqs. 50-51): the fraction of a source's energy on each pixel for any
// sub-pixel position, from tables that the exact FFT path (system_psf.hpp)
// fills once per sensor, instead of one FFT per position.
//
// E(u) is the fraction of a source's energy on a pixel whose centre lies u
// pixels (u_x, u_y) from it (eq. 51; E(-u) = E(u), the OTF being radial). A
// source at pixel coordinates (x, y) (0 = centre of pixel 0) belongs to its
// nearest pixel (cx, cy); with phi = (x - cx, y - cy) in [-1/2, 1/2]^2, pixel
// (cx + d_x, cy + d_y) receives E(d - phi), for |d|inf <= H (H: the point PSF
// reach, the window of energy_on_detector). E is band-limited at
// 1 / (lambda F#), so it varies with phi on that scale. Two regions:
//  - core, |d|inf <= c: E at S offsets per pixel along each axis
//    (point_offset_steps_per_lambda_f), Catmull-Rom cubic in phi. One grid
//    and one set of weights (summing to one) for the whole box, so the
//    box's total is interpolated between exact totals, which hardly vary;
//  - tail, c < |d|inf <= H (point_tail):
//    direct: E at 2 offsets per pixel, linear in phi, pixel by pixel;
//    multilevel: the core holds E w instead, w(u) = taper(|u_x|, a)
//      taper(|u_y|, a) stepping from 1 at a to 0 at 2a = c (a from
//      point_core_reach, at least 2 pixels), and E0 (1 - w), E0 = E at
//      phi = 0, goes through grids shared by all sources
//      (point_source_halo.hpp): cost per frame, not per source.
// The tables are pixel_integrated_psf sampled every pitch / S with an FFT
// period of at least twice the table's extent and 64 (lambda F# / pitch)^(1/3)
// pixels (one FFT per table, or m x m interleaved ones at m times the step
// where a 2048-point FFT would not reach that period): the copies of the PSF
// that alias into a table then hold below 1e-6 of the energy per pixel. The
// FFT is the smallest even size with factors 2, 3, 5, 7 that holds that
// period (point_table_fft_sizes fitted; power_of_two: the next power of
// two, as before, up to 4x the points).
// (energy_on_detector's own period is its window plus 9 steps: a window
// near psf_grid_size wraps the energy beyond it back in, 1e-3 for a
// Nyquist-sampled sensor's 511-pixel window at the default 512.)
//
// Memory (4-byte floats): core (2c + 1)^2 (S + 3)^2, direct tail
// (2H + 1)^2 9, halo kernels <= 169 doubles per level; bytes() tells. For the
// spec 7.6 Table 3 sensor (100.2 um pixels = 11.45 lambda F#, H = 44, a = 2,
// c = 4, S = 46): 778 + 285 KB, 1.07 MB in all. For a Nyquist-sampled
// 256 x 256 sensor (pixel = lambda F# / 2, H = 255, a = 16, c = 32, S = 2):
// 423 KB + 9.4 MB, 9.8 MB in all. point_table_max_mib bounds the total: S
// (then a) is reduced, and the direct tail dropped, to stay within it (three
// quarters for the core, a quarter for the tail); at the default 64 MiB, S
// falls below 4 per lambda F# only for pixels wider than about 100 lambda F#
// (where the 2048-point FFT also shortens the core table's period to a few
// pixels: the accuracy then degrades, to about 1 % for 140 lambda F#).
// Pixels wider than 16 lambda F# (separable_pixels) instead hold the core as
// two 1-D tables, E(u) = E_x(u_x) E_y(u_y) (core_x, core_y: S + 3 offsets of
// 2c + 1 pixels, within the same bound), from pixel_integrated_lsf, plus
// the corner terms of the PSF's quadrant energies (corner_correction.hpp),
// evaluated for each source at its own offset over the core box; their
// tails (and E0) come from the same sum at their offsets. Built in a few
// milliseconds at any width (G's table, a few ms more, kept per optics),
// where the 2-D fold takes 0.2 s at 18 lambda F# and seconds from 140 on.
// With point_wide_pixels product (as before): the plain product, from 32
// lambda F#.
// Build: one FFT of up to 2048^2 points per table, 45-65 ms for the sensors
// above on a 2-core machine (70-90 ms at power_of_two sizes; about 2 ms for
// a 64 x 64 array of 0.8 lambda F# pixels).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "core/fidelity.hpp"
#include "geometry/sample_grid.hpp"
#include "sensor/corner_correction.hpp"
#include "sensor/otf.hpp"
#include "sensor/point_source_halo.hpp"

namespace eoir::sensor {

struct PointSourceModel {
  std::int64_t window_half = 0;  // H, pixels (point_psf_reach)
  std::int64_t taper_start = 0;  // a, pixels (point_core_reach, >= 2)
  std::int64_t core_half = 0;    // c = min(2a, H), pixels (H when H <= a)
  std::int64_t core_steps = 0;   // S, offsets per pixel of the core table
  static constexpr std::int64_t tail_steps = 2;  // offsets per pixel of the direct tail table
  // core[(i_y (S + 3) + i_x) (2c + 1)^2 + (d_y + c)(2c + 1) + d_x + c] = E(d -
  // phi) at phi = -1/2 + (i - 1) / S, i = 0..S + 2 (one offset beyond each
  // end for the cubic).
  std::vector<float> core;
  // Pixels wider than 16 lambda F# (separable_pixels): the core instead as
  // E_x(d_x - phi_x) E_y(d_y - phi_y), the pixel-integrated line-spread
  // functions, each at the same S + 3 offsets:
  // core_x[i (2c + 1) + d + c] = E_x(d - phi_i) (core_y likewise); core empty.
  bool separable = false;
  std::vector<double> core_x, core_y;
  // With it (point_wide_pixels quadrant), the corner terms of G
  // (corner_correction.hpp), added for each source at its own offset over
  // the core box (and in the direct tail and E0 at their offsets);
  // pixel_x_lf, pixel_y_lf: the pitch in lambda F#. Null: the plain product.
  std::shared_ptr<const CornerCorrection> corners;
  double pixel_x_lf = 0, pixel_y_lf = 0;
  // tail[(i_y 3 + i_x) (2H + 1)^2 + (d_y + H)(2H + 1) + d_x + H]: the same at
  // phi = -1/2 + i / 2, zero on the core box; empty when over the memory
  // bound (or without a tail).
  std::vector<float> tail;
  std::vector<HaloLevel> halo;  // the multilevel tail, from E0 (1 - w)
  PointTail tail_mode = PointTail::automatic;
  // Streak sub-steps per pixel of displacement along x and y
  // (streak_steps_per_pixel and streak_steps_per_lambda_f).
  double streak_steps_per_pixel_x = 1, streak_steps_per_pixel_y = 1;
  double build_s = 0;  // wall time of the build

  bool has_tail() const { return core_half < window_half; }
  bool has_direct_tail() const { return !tail.empty(); }
  std::int64_t bytes() const;
};

// Builds the model for a sensor's optics and pixel grid (pitch and array
// size, which clamps the window as energy_on_detector's FFT does).
PointSourceModel build_point_source_model(const OpticsModel& optics, const geometry::SampleGrid& grid,
                                          const Fidelity& fidelity);

// Whether the tables come from the product of pixel-integrated line-spread
// functions (with the corner terms of G: pixels wider than 16 lambda F#;
// with point_wide_pixels product, the plain product from 32 lambda F#;
// point_source_model.cpp) rather than 2-D FFTs of the OTF.
bool separable_pixels(const OpticsModel& optics, const geometry::SampleGrid& grid, const Fidelity& fidelity = {});

// The window half-width H in pixels for point sources: the reach of
// fidelity.point_psf_reach, at least 2, at most the array's larger side and
// (psf_grid_size - 2) / 2 (energy_on_detector's FFT must hold the window).
std::int64_t point_window_half(const OpticsModel& optics, const geometry::SampleGrid& grid, const Fidelity& fidelity);

}  // namespace eoir::sensor
