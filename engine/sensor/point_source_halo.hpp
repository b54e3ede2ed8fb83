// The far part of the point sources' energy on detector (eq. 51), for all the
// sources of a frame at once: the multilevel tail of point_source_model.hpp.
//
// Beyond a pixels from a source its pixel-integrated PSF E is small and
// smooth, so it need not be added pixel by pixel for every source. It is
// split over nested grids of spacing h_l = a 2^(l-1) pixels (l = 1..L, nodes
// at pixel multiples of h_l, every node of level l + 1 a node of level l):
//   T_l(d) = E0(d) [w_(l+1)(d) - w_l(d)],  w_l(d) = taper(|d_x|, h_l) taper(|d_y|, h_l),
// w_(L+1) = 1 on the window, E0 the energy on detector at zero offset. Each
// source is spread onto the two nearest nodes along each axis of every level
// (bilinear weights), each level's node values are convolved with its kernel
// K_l(J) = (1 / h^2) sum_d T_l(d) tent(d_x / h - J_x) tent(d_y / h - J_y)
// (T_l averaged with tent weights about node offset J: the rings of an
// oversampled Airy tail are averaged, not point-sampled), and the levels are
// interpolated back to pixels, coarsest first. Tents sum to one over the
// nodes and to h over the pixels, so each level adds exactly
// h^2 sum_J K_l(J) = sum_d T_l(d) of energy (less what falls off the array).
// T_l vanishes beyond 4 h_l: each kernel has a reach of at most 4 nodes.
//
// Cost per frame: about 81 multiply-adds per node of each level (level 1 has
// (pixels / a)^2 nodes) plus 4 per pixel, and 4 per source and level.
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
// >= 1): empty when the window ends before a.
std::vector<HaloLevel> halo_levels(const FocalPlaneSamples& e0, std::int64_t taper_start_px);

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
  struct Grid {
    const HaloLevel* level;
    std::int64_t nodes_x, nodes_y;  // output nodes 0..nodes - 1 cover the image
    std::int64_t reach;             // input nodes run from -reach to nodes - 1 + reach
    std::vector<double> input;      // (nodes_x + 2 reach) x (nodes_y + 2 reach)
    std::vector<double> output;     // nodes_x x nodes_y
    std::vector<char> row_used;     // input rows holding any source
  };
  std::vector<Grid> grids_;
  std::int64_t width_, height_;
};

}  // namespace eoir::sensor
