#include "sensor/point_source_halo.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::sensor {
namespace {

double tent(double t) { return std::max(0.0, 1.0 - std::abs(t)); }

// Output nodes 0..M with M h >= size - 1: every pixel lies between two nodes.
std::int64_t nodes_covering(std::int64_t size_px, std::int64_t spacing_px) {
  return (std::max<std::int64_t>(size_px, 1) - 1 + spacing_px - 1) / spacing_px + 1;
}

// Linear interpolation along one axis from nodes at multiples of `ratio`
// (in units of the destination's nodes) to every destination node:
// dst[i * dst_stride] += src at i / ratio, for i < dst_count.
void interpolate_line(const double* src, std::int64_t src_stride, double* dst, std::int64_t dst_stride,
                      std::int64_t dst_count, std::int64_t ratio) {
  for (std::int64_t i = 0; i < dst_count; ++i) {
    const std::int64_t n = i / ratio, r = i - n * ratio;
    double v = src[n * src_stride];
    if (r != 0) {
      const double f = static_cast<double>(r) / static_cast<double>(ratio);
      v += f * (src[(n + 1) * src_stride] - v);
    }
    dst[i * dst_stride] += v;
  }
}

// Adds the bilinear interpolation of `coarse` (nodes_x x nodes_y, spacing
// `ratio` destination nodes) to `fine` (fine_x x fine_y).
void interpolate(const std::vector<double>& coarse, std::int64_t nodes_x, std::int64_t nodes_y, std::int64_t ratio,
                 double* fine, std::int64_t fine_x, std::int64_t fine_y) {
  std::vector<double> rows(static_cast<std::size_t>(nodes_y * fine_x), 0.0);  // along x first
  for (std::int64_t r = 0; r < nodes_y; ++r)
    interpolate_line(&coarse[static_cast<std::size_t>(r * nodes_x)], 1, &rows[static_cast<std::size_t>(r * fine_x)], 1,
                     fine_x, ratio);
  for (std::int64_t c = 0; c < fine_x; ++c)
    interpolate_line(&rows[static_cast<std::size_t>(c)], fine_x, fine + c, fine_x, fine_y, ratio);
}

}  // namespace

double taper(double r, double a) {
  const double t = (r - a) / a;
  if (t <= 0) return 1.0;
  if (t >= 1) return 0.0;
  return 1.0 - t * t * (3.0 - 2.0 * t);
}

std::vector<HaloLevel> halo_levels(const FocalPlaneSamples& e0, std::int64_t taper_start_px) {
  std::vector<HaloLevel> levels;
  const std::int64_t half = e0.half(), a = std::max<std::int64_t>(1, taper_start_px);
  if (half <= a) return levels;  // w_1 = 1 on the whole window: nothing beyond the core
  std::int64_t count = 1;
  while (a << count < half) ++count;  // w_(L+1) = 1 on the window once a 2^L >= H
  for (std::int64_t l = 1; l <= count; ++l) {
    const std::int64_t h = a << (l - 1);
    const double hd = static_cast<double>(h);
    const bool last = l == count;
    const std::int64_t r0 = (std::min(4 * h, half) + h - 1) / h + 1;
    const std::int64_t side0 = 2 * r0 + 1;
    std::vector<double> k(static_cast<std::size_t>(side0 * side0), 0.0);
    for (std::int64_t dy = -half; dy <= half; ++dy)
      for (std::int64_t dx = -half; dx <= half; ++dx) {
        const double ax = std::abs(static_cast<double>(dx)), ay = std::abs(static_cast<double>(dy));
        const double inner = taper(ax, hd) * taper(ay, hd);
        const double outer = last ? 1.0 : taper(ax, 2 * hd) * taper(ay, 2 * hd);
        const double t = e0.at(dx, dy) * (outer - inner) / (hd * hd);
        if (t == 0) continue;
        const auto jx0 = static_cast<std::int64_t>(std::floor(static_cast<double>(dx) / hd));
        const auto jy0 = static_cast<std::int64_t>(std::floor(static_cast<double>(dy) / hd));
        for (std::int64_t jy = jy0; jy <= jy0 + 1; ++jy)
          for (std::int64_t jx = jx0; jx <= jx0 + 1; ++jx) {
            const double w = tent(static_cast<double>(dx) / hd - static_cast<double>(jx)) *
                             tent(static_cast<double>(dy) / hd - static_cast<double>(jy));
            if (w > 0) k[static_cast<std::size_t>((jy + r0) * side0 + jx + r0)] += t * w;
          }
      }
    // Trim to the nodes that hold anything.
    std::int64_t reach = 0;
    for (std::int64_t jy = -r0; jy <= r0; ++jy)
      for (std::int64_t jx = -r0; jx <= r0; ++jx)
        if (k[static_cast<std::size_t>((jy + r0) * side0 + jx + r0)] != 0)
          reach = std::max({reach, std::abs(jx), std::abs(jy)});
    HaloLevel level;
    level.spacing_px = h;
    level.reach_nodes = reach;
    const std::int64_t side = 2 * reach + 1;
    level.kernel.resize(static_cast<std::size_t>(side * side));
    for (std::int64_t jy = -reach; jy <= reach; ++jy)
      for (std::int64_t jx = -reach; jx <= reach; ++jx)
        level.kernel[static_cast<std::size_t>((jy + reach) * side + jx + reach)] =
            k[static_cast<std::size_t>((jy + r0) * side0 + jx + r0)];
    levels.push_back(std::move(level));
  }
  return levels;
}

HaloGrids::HaloGrids(const std::vector<HaloLevel>& levels, std::int64_t width, std::int64_t height)
    : width_(width), height_(height) {
  for (const HaloLevel& level : levels) {
    Grid g;
    g.level = &level;
    g.nodes_x = nodes_covering(width, level.spacing_px);
    g.nodes_y = nodes_covering(height, level.spacing_px);
    g.reach = level.reach_nodes;
    const std::int64_t rows = g.nodes_y + 2 * g.reach;
    g.input.assign(static_cast<std::size_t>((g.nodes_x + 2 * g.reach) * rows), 0.0);
    g.row_used.assign(static_cast<std::size_t>(rows), 0);
    grids_.push_back(std::move(g));
  }
}

void HaloGrids::spread(double x_px, double y_px, double electrons) {
  for (Grid& g : grids_) {
    const double h = static_cast<double>(g.level->spacing_px);
    const double gx = x_px / h, gy = y_px / h;
    const double fx0 = std::floor(gx), fy0 = std::floor(gy);
    const double fx = gx - fx0, fy = gy - fy0;
    const auto nx0 = static_cast<std::int64_t>(fx0), ny0 = static_cast<std::int64_t>(fy0);
    const std::int64_t stride = g.nodes_x + 2 * g.reach;
    for (std::int64_t b = 0; b <= 1; ++b) {
      const std::int64_t ny = ny0 + b;
      if (ny < -g.reach || ny >= g.nodes_y + g.reach) continue;  // too far off to reach the image
      const double wy = b ? fy : 1.0 - fy;
      for (std::int64_t a = 0; a <= 1; ++a) {
        const std::int64_t nx = nx0 + a;
        if (nx < -g.reach || nx >= g.nodes_x + g.reach) continue;
        const double wx = a ? fx : 1.0 - fx;
        g.input[static_cast<std::size_t>((ny + g.reach) * stride + nx + g.reach)] += electrons * wx * wy;
        g.row_used[static_cast<std::size_t>(ny + g.reach)] = 1;
      }
    }
  }
}

void HaloGrids::add_to(std::vector<double>& image) {
  if (grids_.empty()) return;
  // Convolve each level: output(m) = sum_J K(J) input(m - J).
  for (Grid& g : grids_) {
    g.output.assign(static_cast<std::size_t>(g.nodes_x * g.nodes_y), 0.0);
    const std::int64_t r = g.reach, side = 2 * r + 1, stride = g.nodes_x + 2 * r;
    const std::vector<double>& k = g.level->kernel;
    for (std::int64_t iy = 0; iy < g.nodes_y + 2 * r; ++iy) {
      if (!g.row_used[static_cast<std::size_t>(iy)]) continue;
      for (std::int64_t jy = -r; jy <= r; ++jy) {
        const std::int64_t my = iy - r + jy;
        if (my < 0 || my >= g.nodes_y) continue;
        double* __restrict out = &g.output[static_cast<std::size_t>(my * g.nodes_x)];
        for (std::int64_t jx = -r; jx <= r; ++jx) {
          const double kv = k[static_cast<std::size_t>((jy + r) * side + jx + r)];
          if (kv == 0) continue;
          const double* __restrict in = &g.input[static_cast<std::size_t>(iy * stride + r - jx)];
          for (std::int64_t mx = 0; mx < g.nodes_x; ++mx) out[mx] += kv * in[mx];
        }
      }
    }
  }
  // Coarsest to finest: each level interpolated onto the next finer one.
  for (std::size_t l = grids_.size() - 1; l > 0; --l) {
    const Grid& coarse = grids_[l];
    Grid& fine = grids_[l - 1];
    interpolate(coarse.output, coarse.nodes_x, coarse.nodes_y, 2, fine.output.data(), fine.nodes_x, fine.nodes_y);
  }
  const Grid& first = grids_.front();
  interpolate(first.output, first.nodes_x, first.nodes_y, first.level->spacing_px, image.data(), width_, height_);
}

double HaloGrids::cost(const std::vector<HaloLevel>& levels, std::int64_t width, std::int64_t height) {
  double total = 4.0 * static_cast<double>(width) * static_cast<double>(height);
  for (const HaloLevel& level : levels) {
    const double side = static_cast<double>(2 * level.reach_nodes + 1);
    const auto nx = static_cast<double>(nodes_covering(width, level.spacing_px));
    const auto ny = static_cast<double>(nodes_covering(height, level.spacing_px));
    total += (nx + side) * (ny + side) * side * side;
  }
  return total;
}

}  // namespace eoir::sensor
