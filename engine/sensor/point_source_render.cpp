#include "sensor/point_source_render.hpp"

#include <algorithm>
#include <cmath>

#include "sensor/catmull_rom.hpp"

namespace eoir::sensor {
namespace {

// A source's nearest pixel and its offset phi = position - pixel, in [-1/2, 1/2].
struct Anchor {
  std::int64_t pixel;
  double offset;
};
Anchor anchor(double position_px) {
  const double nearest = std::floor(position_px + 0.5);
  return {static_cast<std::int64_t>(nearest), position_px - nearest};
}

// Catmull-Rom weights at offset phi on a table with `steps` offsets per pixel
// whose entry k holds phi = -1/2 + (k - 1) / steps: entries first..first + 3.
void cubic_weights(double phi, std::int64_t steps, std::int64_t& first, double w[4]) {
  const double t = (phi + 0.5) * static_cast<double>(steps);
  first = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(t)), 0, steps - 1);
  catmull_rom_weights(t - static_cast<double>(first), w);
}

// Linear weights on a table whose entry k holds phi = -1/2 + k / steps:
// entries first and first + 1 with weights 1 - f and f.
void linear_weights(double phi, std::int64_t steps, std::int64_t& first, double& f) {
  const double t = (phi + 0.5) * static_cast<double>(steps);
  first = std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(t)), 0, steps - 1);
  f = t - static_cast<double>(first);
}

struct Image {
  double* values;
  std::int64_t width, height;
};

struct Scratch {
  std::vector<float> acc;       // the core box
  std::vector<double> taper_x;  // w along x
  std::vector<double> along_x, along_y;  // the separable core's factors
  std::vector<double> corners;           // and G at the core box's pixel corners
};

// The corner terms of G (corner_correction.hpp) added to the separable core
// box `a` of a source at offset (phi_x, phi_y): corner k (k = -c - 1 .. c)
// lies k + 1/2 - phi pixels from the source, and pixel d spans corners d - 1
// and d: G(d, d) - G(d - 1, d) - G(d, d - 1) + G(d - 1, d - 1).
void add_corner_terms(const PointSourceModel& m, double phi_x, double phi_y, std::int64_t x_lo, std::int64_t x_hi,
                      std::int64_t y_lo, std::int64_t y_hi, float* a, std::vector<double>& g) {
  const std::int64_t c = m.core_half, box = 2 * c + 1, n = box + 1;
  g.resize(static_cast<std::size_t>(n * n));
  for (std::int64_t ky = y_lo - 1; ky <= y_hi; ++ky) {
    const double y_lf = (static_cast<double>(ky) + 0.5 - phi_y) * m.pixel_y_lf;
    for (std::int64_t kx = x_lo - 1; kx <= x_hi; ++kx)
      g[static_cast<std::size_t>((ky + c + 1) * n + kx + c + 1)] =
          m.corners->at((static_cast<double>(kx) + 0.5 - phi_x) * m.pixel_x_lf, y_lf);
  }
  for (std::int64_t dy = y_lo; dy <= y_hi; ++dy) {
    const double* g1 = &g[static_cast<std::size_t>((dy + c + 1) * n + c + 1)];
    const double* g0 = g1 - n;
    float* row = a + (dy + c) * box + c;
    for (std::int64_t dx = x_lo; dx <= x_hi; ++dx)
      row[dx] = static_cast<float>(static_cast<double>(row[dx]) + g1[dx] - g1[dx - 1] - g0[dx] + g0[dx - 1]);
  }
}

// The core box of one source, cubic in the offset, multiplied by the taper w
// when the tail is multilevel.
void add_core(const PointSourceModel& m, double x, double y, double electrons, bool tapered, const Image& im,
              Scratch& scratch) {
  const Anchor ax = anchor(x), ay = anchor(y);
  const std::int64_t c = m.core_half, box = 2 * c + 1;
  if (ax.pixel + c < 0 || ay.pixel + c < 0 || ax.pixel - c >= im.width || ay.pixel - c >= im.height) return;
  const std::int64_t x_lo = std::max(-c, -ax.pixel), x_hi = std::min(c, im.width - 1 - ax.pixel);
  const std::int64_t y_lo = std::max(-c, -ay.pixel), y_hi = std::min(c, im.height - 1 - ay.pixel);
  const std::int64_t s = m.core_steps, offsets = s + 3;
  std::int64_t ix = 0, iy = 0;
  double wx[4], wy[4];
  cubic_weights(ax.offset, s, ix, wx);
  cubic_weights(ay.offset, s, iy, wy);
  // The rows of the box on the image, accumulated over the 16 offsets.
  const std::size_t area = static_cast<std::size_t>(box * box);
  const std::size_t from = static_cast<std::size_t>((y_lo + c) * box), to = static_cast<std::size_t>((y_hi + c + 1) * box);
  std::vector<float>& acc = scratch.acc;
  acc.assign(area, 0.0f);
  float* __restrict a = acc.data();
  if (m.separable) {
    // E_y(d_y - phi_y) E_x(d_x - phi_x), each cubic in its own offset.
    scratch.along_x.assign(static_cast<std::size_t>(box), 0.0);
    scratch.along_y.assign(static_cast<std::size_t>(box), 0.0);
    for (int k = 0; k < 4; ++k)
      for (std::int64_t d = 0; d < box; ++d) {
        scratch.along_x[static_cast<std::size_t>(d)] += wx[k] * m.core_x[static_cast<std::size_t>((ix + k) * box + d)];
        scratch.along_y[static_cast<std::size_t>(d)] += wy[k] * m.core_y[static_cast<std::size_t>((iy + k) * box + d)];
      }
    for (std::size_t i = from; i < to; ++i)
      a[i] = static_cast<float>(scratch.along_y[i / static_cast<std::size_t>(box)] *
                                scratch.along_x[i % static_cast<std::size_t>(box)]);
    if (m.corners) add_corner_terms(m, ax.offset, ay.offset, x_lo, x_hi, y_lo, y_hi, a, scratch.corners);
  } else {
    for (int b = 0; b < 4; ++b)
      for (int k = 0; k < 4; ++k) {
        const auto w = static_cast<float>(wy[b] * wx[k]);
        const float* __restrict t = &m.core[static_cast<std::size_t>((iy + b) * offsets + ix + k) * area];
        for (std::size_t i = from; i < to; ++i) a[i] += w * t[i];
      }
  }
  const double start = static_cast<double>(m.taper_start);
  const double* tx = nullptr;
  if (tapered) {
    scratch.taper_x.resize(static_cast<std::size_t>(box));
    for (std::int64_t dx = -c; dx <= c; ++dx)
      scratch.taper_x[static_cast<std::size_t>(dx + c)] = taper(std::abs(static_cast<double>(dx) - ax.offset), start);
    tx = scratch.taper_x.data() + c;
  }
  for (std::int64_t dy = y_lo; dy <= y_hi; ++dy) {
    const double ty = tapered ? taper(std::abs(static_cast<double>(dy) - ay.offset), start) : 1.0;
    if (ty == 0) continue;
    const double scale = electrons * ty;
    const float* row_acc = a + (dy + c) * box + c;
    double* row = im.values + (ay.pixel + dy) * im.width + ax.pixel;
    if (tapered) {
      for (std::int64_t dx = x_lo; dx <= x_hi; ++dx) row[dx] += scale * tx[dx] * static_cast<double>(row_acc[dx]);
    } else {
      for (std::int64_t dx = x_lo; dx <= x_hi; ++dx) row[dx] += scale * static_cast<double>(row_acc[dx]);
    }
  }
}

// The direct tail of one source about one anchor pixel: the weights of the
// table's 3 x 3 half-pixel offsets (bilinear in phi), summed over the
// sub-steps of a streak that share the anchor (the same sum as adding each
// sub-step's window, for one pass over the window per four offsets).
struct TailAnchor {
  std::int64_t x = 0, y = 0;
  double w[3][3] = {};
};

// Adds a sub-step at (x, y) of `electrons` to the anchors of its source.
void add_to_anchors(std::vector<TailAnchor>& anchors, double x, double y, double electrons) {
  const Anchor ax = anchor(x), ay = anchor(y);
  TailAnchor* t = nullptr;
  for (auto it = anchors.rbegin(); it != anchors.rend() && !t; ++it)
    if (it->x == ax.pixel && it->y == ay.pixel) t = &*it;
  if (!t) {
    anchors.emplace_back();
    t = &anchors.back();
    t->x = ax.pixel;
    t->y = ay.pixel;
  }
  std::int64_t ix = 0, iy = 0;
  double fx = 0, fy = 0;
  linear_weights(ax.offset, PointSourceModel::tail_steps, ix, fx);
  linear_weights(ay.offset, PointSourceModel::tail_steps, iy, fy);
  t->w[iy][ix] += electrons * (1 - fx) * (1 - fy);
  t->w[iy][ix + 1] += electrons * fx * (1 - fy);
  t->w[iy + 1][ix] += electrons * (1 - fx) * fy;
  t->w[iy + 1][ix + 1] += electrons * fx * fy;
}

// The direct tail about one anchor: the window beyond the core box.
void add_tail(const PointSourceModel& m, const TailAnchor& t, const Image& im) {
  const std::int64_t h = m.window_half, c = m.core_half, window = 2 * h + 1;
  if (t.x + h < 0 || t.y + h < 0 || t.x - h >= im.width || t.y - h >= im.height) return;
  constexpr std::int64_t offsets = PointSourceModel::tail_steps + 1;
  const std::size_t area = static_cast<std::size_t>(window * window);
  // The offsets in use, four per pass (a source at rest needs one pass).
  std::vector<std::pair<double, const float*>> used;
  for (std::int64_t iy = 0; iy < offsets; ++iy)
    for (std::int64_t ix = 0; ix < offsets; ++ix)
      if (t.w[iy][ix] != 0) used.emplace_back(t.w[iy][ix], &m.tail[static_cast<std::size_t>(iy * offsets + ix) * area]);
  if (used.empty()) return;
  while (used.size() % 4) used.emplace_back(0.0, used.front().second);
  const std::int64_t x_lo = std::max(-h, -t.x), x_hi = std::min(h, im.width - 1 - t.x);
  const std::int64_t y_lo = std::max(-h, -t.y), y_hi = std::min(h, im.height - 1 - t.y);
  for (std::size_t p = 0; p < used.size(); p += 4) {
    const double w0 = used[p].first, w1 = used[p + 1].first, w2 = used[p + 2].first, w3 = used[p + 3].first;
    const float *t0 = used[p].second, *t1 = used[p + 1].second, *t2 = used[p + 2].second, *t3 = used[p + 3].second;
    auto span = [&](std::int64_t dy, std::int64_t from, std::int64_t to) {
      const std::size_t o = static_cast<std::size_t>((dy + h) * window + h);
      double* row = im.values + (t.y + dy) * im.width + t.x;
      for (std::int64_t dx = from; dx <= to; ++dx) {
        const std::size_t k = o + static_cast<std::size_t>(dx);
        row[dx] += w0 * static_cast<double>(t0[k]) + w1 * static_cast<double>(t1[k]) +
                   w2 * static_cast<double>(t2[k]) + w3 * static_cast<double>(t3[k]);
      }
    };
    for (std::int64_t dy = y_lo; dy <= y_hi; ++dy) {
      if (std::abs(dy) > c) {
        span(dy, x_lo, x_hi);
      } else {  // the core box is the core's
        span(dy, x_lo, std::min(x_hi, -c - 1));
        span(dy, std::max(x_lo, c + 1), x_hi);
      }
    }
  }
}

const std::vector<HaloLevel> no_levels;
// Automatic tail: direct while it costs at most this many multiply-adds per
// frame (tens of ms) or no more than kMultilevelSaving times the multilevel one.
constexpr double kDirectBudget = 33554432.0;
constexpr double kMultilevelSaving = 4.0;

}  // namespace

std::int64_t streak_steps(const PointSourceModel& m, const PointSourceSignal& s) {
  const double steps = std::max(std::abs(s.streak_x_px) * m.streak_steps_per_pixel_x,
                                std::abs(s.streak_y_px) * m.streak_steps_per_pixel_y);
  return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(steps - 1e-9)));
}

PointTail render_point_sources(const PointSourceModel& m, const std::vector<PointSourceSignal>& sources,
                               std::int64_t width, std::int64_t height, std::vector<double>& image) {
  PointTail mode = m.tail_mode;
  if (!m.has_tail()) {
    mode = PointTail::direct;  // the core covers the window
  } else {
    if (mode == PointTail::automatic) {
      // The direct tail is the more faithful (each source's own window, no
      // grid): kept unless it is costly and the multilevel one saves more
      // than kMultilevelSaving times its multiply-adds. A source passes over
      // about 1 + |streak_x| + |streak_y| anchor pixels, 4 offsets each.
      const double box = static_cast<double>(2 * m.core_half + 1), window = static_cast<double>(2 * m.window_half + 1);
      double anchors = 0;
      for (const PointSourceSignal& s : sources)
        anchors += 1.0 + std::ceil(std::abs(s.streak_x_px)) + std::ceil(std::abs(s.streak_y_px));
      const double direct_cost = 4.0 * anchors * (window * window - box * box);
      mode = m.has_direct_tail() &&
                     (direct_cost <= kDirectBudget ||
                      direct_cost <= kMultilevelSaving * HaloGrids::cost(m.halo, width, height))
                 ? PointTail::direct
                 : PointTail::multilevel;
    }
    if (mode == PointTail::direct && !m.has_direct_tail()) mode = PointTail::multilevel;
  }
  const bool multilevel = mode == PointTail::multilevel, direct_tail = !multilevel && m.has_tail();
  HaloGrids halo(multilevel ? m.halo : no_levels, width, height);
  const Image im{image.data(), width, height};
  Scratch scratch;
  std::vector<TailAnchor> anchors;
  for (const PointSourceSignal& s : sources) {
    const std::int64_t n = streak_steps(m, s);
    const double e = s.electrons / static_cast<double>(n);
    for (std::int64_t k = 0; k < n; ++k) {
      const double along = (static_cast<double>(k) + 0.5) / static_cast<double>(n) - 0.5;  // midpoints, -1/2..1/2
      const double x = s.x_px + along * s.streak_x_px, y = s.y_px + along * s.streak_y_px;
      add_core(m, x, y, e, multilevel, im, scratch);
      if (multilevel)
        halo.spread(x, y, e);
      else if (direct_tail)
        add_to_anchors(anchors, x, y, e);
    }
    for (const TailAnchor& t : anchors) add_tail(m, t, im);
    anchors.clear();
  }
  if (multilevel) halo.add_to(image);
  return mode;
}

}  // namespace eoir::sensor
