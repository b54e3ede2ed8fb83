#include "sensor/point_source_halo.hpp"

#include <algorithm>
#include <cmath>

#include "core/parallel_ranges.hpp"
#include "sensor/catmull_rom.hpp"

namespace eoir::sensor {
namespace {

constexpr std::int64_t kPad = 2;  // output nodes beyond the image's on each side (the cubic's reach)

// Index of the last node at spacing h with last * h >= size - 1: nodes
// 0..last span the image.
std::int64_t last_node(std::int64_t size_px, std::int64_t spacing_px) {
  return (std::max<std::int64_t>(size_px, 1) - 1 + spacing_px - 1) / spacing_px;
}

struct NodeRange {
  std::int64_t first, count;  // node index of element 0, element count
};

// The Catmull-Rom taps that interpolate nodes `src` at node coordinate
// (dst_first + i) / ratio, for each element i of `dst`: element indices of
// src and weights. A tap beyond src gets weight 0 (it falls where the weight
// is zero, or serves no pixel of the image).
struct Taps {
  std::int64_t index[4];
  double weight[4];
};
std::vector<Taps> taps_of(NodeRange src, NodeRange dst, std::int64_t ratio) {
  std::vector<Taps> out(static_cast<std::size_t>(dst.count));
  for (std::int64_t i = 0; i < dst.count; ++i) {
    const std::int64_t at = dst.first + i;
    const std::int64_t n0 = at >= 0 ? at / ratio : -((-at + ratio - 1) / ratio);  // floor(at / ratio)
    Taps& t = out[static_cast<std::size_t>(i)];
    catmull_rom_weights(static_cast<double>(at - n0 * ratio) / static_cast<double>(ratio), t.weight);
    for (int k = 0; k < 4; ++k) {
      t.index[k] = n0 - 1 + k - src.first;
      if (t.index[k] < 0 || t.index[k] >= src.count) {
        t.index[k] = 0;
        t.weight[k] = 0;
      }
    }
  }
  return out;
}

// Adds the bicubic interpolation of `coarse` (nodes cx x cy, spacing `ratio`
// destination nodes) to `fine` (nodes fx x fy, row-major): along x row by
// row, then along y as weighted sums of whole rows.
void interpolate(const std::vector<double>& coarse, NodeRange cx, NodeRange cy, std::int64_t ratio, double* fine,
                 NodeRange fx, NodeRange fy) {
  const std::vector<Taps> tx = taps_of(cx, fx, ratio), ty = taps_of(cy, fy, ratio);
  std::vector<double> rows(static_cast<std::size_t>(cy.count * fx.count));
  for (std::int64_t r = 0; r < cy.count; ++r) {
    const double* src = &coarse[static_cast<std::size_t>(r * cx.count)];
    double* dst = &rows[static_cast<std::size_t>(r * fx.count)];
    for (std::int64_t i = 0; i < fx.count; ++i) {
      const Taps& t = tx[static_cast<std::size_t>(i)];
      dst[i] = t.weight[0] * src[t.index[0]] + t.weight[1] * src[t.index[1]] + t.weight[2] * src[t.index[2]] +
               t.weight[3] * src[t.index[3]];
    }
  }
  for (std::int64_t j = 0; j < fy.count; ++j) {
    const Taps& t = ty[static_cast<std::size_t>(j)];
    double* __restrict dst = fine + j * fx.count;
    for (int k = 0; k < 4; ++k) {
      if (t.weight[k] == 0) continue;
      const double w = t.weight[k];
      const double* __restrict src = &rows[static_cast<std::size_t>(t.index[k] * fx.count)];
      for (std::int64_t i = 0; i < fx.count; ++i) dst[i] += w * src[i];
    }
  }
}

}  // namespace

double taper(double r, double a) {
  const double t = (r - a) / a;
  if (t <= 0) return 1.0;
  if (t >= 1) return 0.0;
  return 1.0 - t * t * (3.0 - 2.0 * t);
}

std::vector<HaloLevel> halo_levels(const FocalPlaneSamples& e0, std::int64_t taper_start_px, bool separable_spread) {
  const std::int64_t half = e0.half(), a = std::max<std::int64_t>(1, taper_start_px);
  if (half <= a) return {};  // w_1 = 1 on the whole window: nothing beyond the core
  std::int64_t count = 1;
  while (a << count < half) ++count;  // w_(L+1) = 1 on the window once a 2^L >= H
  std::vector<HaloLevel> levels(static_cast<std::size_t>(count));
  // Levels in parallel (each made whole by one thread).
  parallel_ranges(
      count, 0,
      [&](std::int64_t first, std::int64_t end) {
        for (std::int64_t l = first + 1; l <= end; ++l) {
          const std::int64_t h = a << (l - 1);
          const double hd = static_cast<double>(h);
          const bool last = l == count;
          const std::int64_t r0 = (std::min(4 * h, half) + h - 1) / h + 2;
          const std::int64_t side0 = 2 * r0 + 1;
          std::vector<double> k(static_cast<std::size_t>(side0 * side0), 0.0);
          // Per offset d along an axis: the tapers, the node below d / h and the
          // Catmull-Rom weights of nodes j0 - 1..j0 + 2 (the same for x and y).
          struct Axis {
            double inner, outer;
            std::int64_t j0;
            double w[4];
          };
          std::vector<Axis> axis(static_cast<std::size_t>(2 * half + 1));
          for (std::int64_t d = -half; d <= half; ++d) {
            Axis& at = axis[static_cast<std::size_t>(d + half)];
            const double ad = std::abs(static_cast<double>(d));
            at.inner = taper(ad, hd);
            at.outer = last ? 1.0 : taper(ad, 2 * hd);
            at.j0 = static_cast<std::int64_t>(std::floor(static_cast<double>(d) / hd));
            for (int b = 0; b < 4; ++b)
              at.w[b] = catmull_rom(static_cast<double>(d) / hd - static_cast<double>(at.j0 - 1 + b));
          }
          // (Where the outer taper is zero so is the inner one, and t = 0.)
          std::int64_t reach_d = half;
          while (reach_d > 0 && axis[static_cast<std::size_t>(reach_d + half)].outer == 0) --reach_d;
          const auto term = [&](const Axis& ax, const Axis& ay, std::int64_t dx, std::int64_t dy) {
            const double inner = ax.inner * ay.inner;
            const double outer = last ? 1.0 : ax.outer * ay.outer;
            return e0.at(dx, dy) * (outer - inner) / (hd * hd);
          };
          if (!separable_spread) {  // node by node
            for (std::int64_t dy = -reach_d; dy <= reach_d; ++dy) {
              const Axis& ay = axis[static_cast<std::size_t>(dy + half)];
              for (std::int64_t dx = -reach_d; dx <= reach_d; ++dx) {
                const Axis& ax = axis[static_cast<std::size_t>(dx + half)];
                const double t = term(ax, ay, dx, dy);
                if (t == 0) continue;
                for (int by = 0; by < 4; ++by) {
                  const double wy = ay.w[by];
                  double* row = &k[static_cast<std::size_t>((ay.j0 - 1 + by + r0) * side0 + ax.j0 - 1 + r0)];
                  for (int bx = 0; bx < 4; ++bx) {
                    const double w = wy * ax.w[bx];
                    if (w != 0) row[bx] += t * w;
                  }
                }
              }
            }
          } else {
            // The weights are a product of x and y ones: each row dy's terms
            // spread along x first (into `spread`), then the row along y
            // (the same sums in another order, in ~1/3 of the operations).
            std::vector<double> spread(static_cast<std::size_t>(side0));
            for (std::int64_t dy = -reach_d; dy <= reach_d; ++dy) {
              const Axis& ay = axis[static_cast<std::size_t>(dy + half)];
              std::fill(spread.begin(), spread.end(), 0.0);
              bool any = false;
              for (std::int64_t dx = -reach_d; dx <= reach_d; ++dx) {
                const Axis& ax = axis[static_cast<std::size_t>(dx + half)];
                const double t = term(ax, ay, dx, dy);
                if (t == 0) continue;
                any = true;
                double* to = &spread[static_cast<std::size_t>(ax.j0 - 1 + r0)];
                for (int bx = 0; bx < 4; ++bx) to[bx] += t * ax.w[bx];
              }
              if (!any) continue;
              for (int by = 0; by < 4; ++by) {
                const double wy = ay.w[by];
                if (wy == 0) continue;
                double* __restrict row = &k[static_cast<std::size_t>((ay.j0 - 1 + by + r0) * side0)];
                const double* __restrict from = spread.data();
                for (std::int64_t j = 0; j < side0; ++j) row[j] += wy * from[j];
              }
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
          levels[static_cast<std::size_t>(l - 1)] = std::move(level);
        }
      },
      1);
  return levels;
}

HaloGrids::HaloGrids(const std::vector<HaloLevel>& levels, std::int64_t width, std::int64_t height)
    : width_(width), height_(height) {
  for (const HaloLevel& level : levels) {
    Grid g;
    g.level = &level;
    g.out_first = -kPad;
    g.out_x = last_node(width, level.spacing_px) + 1 + 2 * kPad;
    g.out_y = last_node(height, level.spacing_px) + 1 + 2 * kPad;
    g.in_first = g.out_first - level.reach_nodes;
    g.in_x = g.out_x + 2 * level.reach_nodes;
    g.in_y = g.out_y + 2 * level.reach_nodes;
    g.input.assign(static_cast<std::size_t>(g.in_x * g.in_y), 0.0);
    g.row_used.assign(static_cast<std::size_t>(g.in_y), 0);
    grids_.push_back(std::move(g));
  }
}

void HaloGrids::spread(double x_px, double y_px, double electrons) {
  for (Grid& g : grids_) {
    const double h = static_cast<double>(g.level->spacing_px);
    const double gx = x_px / h, gy = y_px / h;
    const double fx0 = std::floor(gx), fy0 = std::floor(gy);
    // Nodes n0 - 1..n0 + 2 along each axis, as input array indices.
    const std::int64_t ix0 = static_cast<std::int64_t>(fx0) - 1 - g.in_first;
    const std::int64_t iy0 = static_cast<std::int64_t>(fy0) - 1 - g.in_first;
    if (ix0 + 3 < 0 || iy0 + 3 < 0 || ix0 >= g.in_x || iy0 >= g.in_y) continue;  // too far off to reach the image
    double wx[4], wy[4];
    catmull_rom_weights(gx - fx0, wx);
    catmull_rom_weights(gy - fy0, wy);
    for (std::int64_t b = 0; b < 4; ++b) {
      const std::int64_t iy = iy0 + b;
      if (iy < 0 || iy >= g.in_y || wy[b] == 0) continue;
      const double ey = electrons * wy[b];
      double* row = &g.input[static_cast<std::size_t>(iy * g.in_x)];
      for (std::int64_t a = 0; a < 4; ++a) {
        const std::int64_t ix = ix0 + a;
        if (ix >= 0 && ix < g.in_x) row[ix] += ey * wx[a];
      }
      g.row_used[static_cast<std::size_t>(iy)] = 1;
    }
  }
}

void HaloGrids::add_to(std::vector<double>& image) {
  if (grids_.empty()) return;
  // Convolve each level: output(m) = sum_J K(J) input(m - J); output index o
  // and input index o + R - J hold nodes m and m - J.
  for (Grid& g : grids_) {
    g.output.assign(static_cast<std::size_t>(g.out_x * g.out_y), 0.0);
    const std::int64_t r = g.level->reach_nodes, side = 2 * r + 1;
    const std::vector<double>& k = g.level->kernel;
    for (std::int64_t iy = 0; iy < g.in_y; ++iy) {
      if (!g.row_used[static_cast<std::size_t>(iy)]) continue;
      for (std::int64_t jy = -r; jy <= r; ++jy) {
        const std::int64_t oy = iy - r + jy;
        if (oy < 0 || oy >= g.out_y) continue;
        double* __restrict out = &g.output[static_cast<std::size_t>(oy * g.out_x)];
        for (std::int64_t jx = -r; jx <= r; ++jx) {
          const double kv = k[static_cast<std::size_t>((jy + r) * side + jx + r)];
          if (kv == 0) continue;
          const double* __restrict in = &g.input[static_cast<std::size_t>(iy * g.in_x + r - jx)];
          for (std::int64_t ox = 0; ox < g.out_x; ++ox) out[ox] += kv * in[ox];
        }
      }
    }
  }
  // Coarsest to finest: each level interpolated onto the next finer one.
  for (std::size_t l = grids_.size() - 1; l > 0; --l) {
    const Grid& coarse = grids_[l];
    Grid& fine = grids_[l - 1];
    interpolate(coarse.output, {coarse.out_first, coarse.out_x}, {coarse.out_first, coarse.out_y}, 2,
                fine.output.data(), {fine.out_first, fine.out_x}, {fine.out_first, fine.out_y});
  }
  const Grid& first = grids_.front();
  interpolate(first.output, {first.out_first, first.out_x}, {first.out_first, first.out_y},
              first.level->spacing_px, image.data(), {0, width_}, {0, height_});
}

double HaloGrids::cost(const std::vector<HaloLevel>& levels, std::int64_t width, std::int64_t height) {
  double total = 8.0 * static_cast<double>(width) * static_cast<double>(height);
  for (const HaloLevel& level : levels) {
    const double side = static_cast<double>(2 * level.reach_nodes + 1);
    const auto nx = static_cast<double>(last_node(width, level.spacing_px) + 1 + 2 * kPad);
    const auto ny = static_cast<double>(last_node(height, level.spacing_px) + 1 + 2 * kPad);
    total += nx * (ny + side) * side * side;
  }
  return total;
}

}  // namespace eoir::sensor
