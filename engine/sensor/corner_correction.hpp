// The non-separable part of the system PSF's quadrant energy (spec 5.7,
// eq. 40; eq. 51 for pixels many lambda F# wide).
//
// With Q(x, y) the energy of the PSF in {X < x, Y < y} and C(x) = Q(x, inf)
// the integral of the line-spread function, a pixel [x0, x1] x [y0, y1]
// receives (inclusion-exclusion)
//   E = Q(x1, y1) - Q(x0, y1) - Q(x1, y0) + Q(x0, y0)
//     = (C(x1) - C(x0)) (C(y1) - C(y0)) + G(x1, y1) - G(x0, y1) - G(x1, y0) + G(x0, y0),
// G = Q - C(x) C(y): the product of the pixel-integrated line-spread
// functions (pixel_integrated_lsf) plus the corner terms of G. G is a
// function of x, y in units of lambda F#, not of the pixel: one table per
// optics serves any pitch. G is odd in x and in y (zero on the axes), at
// most about 0.018 (near x = y = 0.75 lambda F#, the diffraction-limited
// PSF), and about 0.019 / r far out: for a source near a pixel corner the
// product alone is off by over 1 % of the source's energy at any pixel
// width.
//
// Computed (lambda F# = 1, cutoff 1) as the sine transform
//   G(x, y) = pi^-2 int_0^1 int_0^1 D(u, v) sin(2 pi u x) sin(2 pi v y) / (u v) du dv,
//   D(u, v) = OTF(sqrt(u^2 + v^2)) - OTF(u) OTF(v)
// (the transform of the quadrant indicator is 1 / ((2 pi i u)(2 pi i v)) off
// the axes, where D vanishes), by the midpoint rule on a grid of step
// `step_lf` out to near_lf (16 lambda F#, more with jitter and defocus);
// beyond it the PSF's tail, A / r^3 with A = s / (4 pi^2) from the OTF's
// slope s at zero frequency (4 / pi for a circular pupil: A = pi^-3),
// integrated over the corner gives
//   G(x, y) = 2 A / (x + y + r) - T(x) T(y),  T = 1 - C,
// within 1e-6 of the transform from 16 lambda F# on (diffraction limited).
// Between the grid's nodes: Catmull-Rom (bicubic); against the Airy pattern
// integrated directly the pixel energies agree within 2e-5. Build: about
// 2.4 ms (67^2 nodes, a 256^2 quadrature) for a diffraction-limited optics,
// growing as near_lf^3 with jitter and defocus; kept per process for each
// optics in lambda F# units (8 at most).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "sensor/otf.hpp"

namespace eoir::sensor {

struct CornerCorrection {
  double near_lf = 0;       // the grid's reach, lambda F#
  double step_lf = 0.25;    // its step, lambda F#
  std::int64_t nodes = 0;   // per axis, from 0 (a margin of 3 past near_lf)
  std::vector<double> g;    // G(i step, j step) at [i nodes + j]
  double tail_step_lf = 0.0625;
  std::vector<double> tail;  // T(k tail_step), k = 0..tail.size() - 1 (past near_lf + 1)
  double tail_coefficient = 0;  // A: PSF ~ A / r^3 far out (lambda F# units)
  double build_s = 0;

  // G(x, y), x and y in lambda F#.
  double at(double x_lf, double y_lf) const;
  // T(x) = 1 - C(x), the LSF's energy beyond x, for x >= 0.
  double beyond(double x_lf) const;
  std::int64_t bytes() const { return static_cast<std::int64_t>((g.size() + tail.size()) * sizeof(double)); }
};

// The correction for an optics (kept process-wide per normalised OTF: the
// same optics in lambda F# units, whatever the pitch, share one).
std::shared_ptr<const CornerCorrection> corner_correction(const OpticsModel& optics, std::int64_t otf_table_size);

}  // namespace eoir::sensor
