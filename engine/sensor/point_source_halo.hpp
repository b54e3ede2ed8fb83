// The far part of the point sources' energy on detector (eq. 51), for all the
// sources of a frame at once: the multilevel tail of point_source_model.hpp.
//
// Beyond a pixels from a source its pixel-integrated PSF E is small and
// smooth, so it need not be added pixel by pixel for every source. It is
// split over nested grids of spacing h_l = a 2^(l-1) pixels (l = 1..L, nodes
// at pixel multiples of h_l, every node of level l + 1 a node of level l):
//   T_l(d) = E0(d) [w_(l+1)(d) - w_l(d)],  w_l(d) = taper(|d_x|, h_l) taper(|d_y|, h_l),
// w_(L+1) = 1 on the window, E0 the energy on detector at zero offset. Each
// source is spread onto the 4 x 4 nodes about it on every level with
// Catmull-Rom weights phi (catmull_rom.hpp), each level's node values are
// convolved with its kernel
//   K_l(J) = (1 / h^2) sum_d T_l(d) phi(d_x / h - J_x) phi(d_y / h - J_y),
// and the levels are interpolated back to pixels with phi, coarsest first.
// phi reproduces quadratics, so spreading and interpolation add no variance
// and K_l has the moments of T_l up to order 2: each level adds exactly the
// energy, centroid offset and second moments of T_l (less what falls off
// the array) wherever the source sits between nodes. (A streak's length,
// or a centroid, measured on the image is then that of the direct path,
// the Airy tail's heavy second moment included.) T_l vanishes beyond 4 h_l:
// each kernel has a reach of at most 6 nodes.
//
// Cost per frame: about (2R + 1)^2 multiply-adds per node of each level with
// a source nearby (level 1 has (pixels / a)^2 nodes) plus 8 per pixel, and 16
// per source and level.
#pragma once
#include <cstdint>
#include <vector>

#include "sensor/system_psf.hpp"

namespace eoir::sensor {

// The smooth step of the tapers: 1 for r <= a, 0 for r >= 2a, 1 - t^2 (3 - 2t)
// with t = (r - a) / a between.
double taper(double r, double a);

struct HaloLevel {
  std::int64_t spacing_px = 0;  // h_l
  std::int64_t reach_nodes = 0;  // R: the kernel covers node offsets [-R, R]^2
  std::vector<double> kernel;    // (2R + 1)^2, row-major: fraction of the energy per pixel
};

// The levels for E0 = energy_on_detector at zero offset on its window
// (|d| <= e0.half()), beyond the taper that starts at `taper_start_px` (a,
// >= 1): empty when the window ends before a. separable_spread: each
// term spread along x, then y (point_table_fft_sizes fitted); false: node by
// node, the sums in their order before it (power_of_two: bit for bit).
std::vector<HaloLevel> halo_levels(const FocalPlaneSamples& e0, std::int64_t taper_start_px, bool separable_spread);

// One frame's grids over a width x height pixel image.
class HaloGrids {
 public:
  HaloGrids(const std::vector<HaloLevel>& levels, std::int64_t width, std::int64_t height);
  // A source of `electrons` at pixel coordinates (x, y) (0 = centre of pixel 0).
  void spread(double x_px, double y_px, double electrons);
  // Convolves, interpolates down the levels and adds the result to `image`
  // (width x height, row-major).
  void add_to(std::vector<double>& image);
  // Multiply-adds of add_to for these levels and image size (to choose
  // between the direct and the multilevel tail).
  static double cost(const std::vector<HaloLevel>& levels, std::int64_t width, std::int64_t height);

 private:
  // Node n of a level sits at pixel n h. Output nodes -pad..last + pad hold
  // what the cubic interpolation to the image (and to the next finer
  // level) reads; input nodes reach R further, the kernel's reach.
  struct Grid {
    const HaloLevel* level;
    std::int64_t out_first, out_x, out_y;  // first output node index, counts along x and y
    std::int64_t in_first, in_x, in_y;     // the same for the input nodes
    std::vector<double> input;             // in_x x in_y
    std::vector<double> output;            // out_x x out_y
    std::vector<char> row_used;            // input rows holding any source
  };
  std::vector<Grid> grids_;
  std::int64_t width_, height_;
};

}  // namespace eoir::sensor
