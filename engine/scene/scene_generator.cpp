#include "scene/scene_generator.hpp"

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

#include "core/parallel_ranges.hpp"
#include "scene/apparent_grid.hpp"

namespace eoir::scene {

SceneImage generate_scene(const World& world, unsigned threads, SceneImage storage) {
  using clock = std::chrono::steady_clock;
  const auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  const auto t0 = clock::now();
  SceneImage out;
  const geometry::SampleGrid& grid = world.grid();
  out.image.grid = grid;

  // Distant area sources (4.1.6.1) at their exact positions (where they
  // appear: scene/apparent_grid.hpp), where they lie inside the field of view
  // and the (geometric) line of sight to them is clear.
  const ApparentGrid apparent(world);
  for (const auto& o : world.objects) {
    if (o->imaging != Imaging::point_source) continue;
    GridPlace p;
    if (!apparent.object(*o, p) || !grid.in_field(p.column, p.row, 1e-4)) continue;
    const geometry::RayQuery others{geometry::ray_mask_all, o->id};
    if (world.caster.occluded(o->seen.position_m / o->range_m, o->range_m, others)) continue;
    out.image.point_sources.push_back(radiometry::PointSource{o->id, -1, p.column, p.row, o->point_irradiance_W_cm2(),
                                                              p.streak_columns, p.streak_rows});
  }
  // Catalogue stars (spec 4.1.6.1), placed and culled with the world's sky.
  for (std::size_t k = 0; k < world.sky.stars.size(); ++k) {
    const WorldStar& s = world.sky.stars[k];
    out.image.point_sources.push_back(radiometry::PointSource{-1, static_cast<std::int32_t>(k), s.column, s.row,
                                                              s.irradiance_W_cm2, s.streak_columns, s.streak_rows});
  }
  const auto t1 = clock::now();

  // Ray-cast the sample grid (spec 4.1.3) against the objects imaged as
  // extended sources and shade only what is hit (WorldObject::radiance_at).
  const std::int64_t w = grid.width(), h = grid.height();
  const std::size_t count = static_cast<std::size_t>(w * h);
  out.hits = std::move(storage.hits);
  out.image.radiance_W_cm2_sr = std::move(storage.image.radiance_W_cm2_sr);
  out.hits.resize(count);  // cast_grid emits every sample once
  out.image.radiance_W_cm2_sr.resize(count);
  const auto direction = [&](std::int64_t c, std::int64_t r) { return world.sample_direction(c, r); };
  const bool sky_varies = world.atmosphere.sky != nullptr;  // under the atmosphere, with the line of sight
  const double background = world.sky.background_radiance_W_cm2_sr;
  // The sky under the atmosphere on a coarse grid (every kSkyStep-th
  // sample): a sample that meets nothing takes the bilinear value of its
  // cell where the cell's corners agree within kSkyAgreement (the sky is
  // smooth there, tabulated itself on degree-wide cells), else its own
  // lookup (the limb's haze, the horizon).
  constexpr std::int64_t kSkyStep = 8;
  constexpr double kSkyAgreement = 1e-3;
  const std::int64_t gw = (w + kSkyStep - 1) / kSkyStep + 1, gh = (h + kSkyStep - 1) / kSkyStep + 1;
  std::vector<double> sky_grid;
  if (sky_varies) {
    sky_grid.resize(static_cast<std::size_t>(gw * gh));
    parallel_ranges(
        gh, threads,
        [&](std::int64_t j0, std::int64_t j1) {
          for (std::int64_t j = j0; j < j1; ++j)
            for (std::int64_t i = 0; i < gw; ++i)
              sky_grid[static_cast<std::size_t>(j * gw + i)] =
                  world.sky_radiance(direction(std::min(i * kSkyStep, w - 1), std::min(j * kSkyStep, h - 1)));
        },
        4);
  }
  const auto sky_at = [&](std::int64_t c, std::int64_t r, const Vec3& d) {
    const std::int64_t i = c / kSkyStep, j = r / kSkyStep;
    const double* g0 = &sky_grid[static_cast<std::size_t>(j * gw + i)];
    const double* g1 = g0 + gw;
    const double lo = std::min({g0[0], g0[1], g1[0], g1[1]}), hi = std::max({g0[0], g0[1], g1[0], g1[1]});
    if (hi - lo > kSkyAgreement * hi) return world.sky_radiance(d.squaredNorm() > 0 ? d : direction(c, r));
    // (the last cell of a row or column may be narrower)
    const double cw = static_cast<double>(std::min((i + 1) * kSkyStep, w - 1) - i * kSkyStep);
    const double ch = static_cast<double>(std::min((j + 1) * kSkyStep, h - 1) - j * kSkyStep);
    const double fx = cw > 0 ? static_cast<double>(c - i * kSkyStep) / cw : 0.0;
    const double fy = ch > 0 ? static_cast<double>(r - j * kSkyStep) / ch : 0.0;
    return (1 - fy) * ((1 - fx) * g0[0] + fx * g0[1]) + fy * ((1 - fx) * g1[0] + fx * g1[1]);
  };
  const geometry::RayQuery extended{geometry::ray_mask_extended, -1};
  world.caster.cast_grid(
      w, h, direction,
      [&](std::int64_t c, std::int64_t r, std::int32_t object, std::int32_t part, std::int32_t facet, double range_m,
          const Vec3& d, const Vec3& normal_frame) {
        const auto i = static_cast<std::size_t>(r * w + c);
        out.hits[i] = SampleHit{object, part};
        if (object < 0) {
          // the background light (spec 4.1.4), or the sky's
          out.image.radiance_W_cm2_sr[i] = sky_varies ? sky_at(c, r, d) : background;
          return;
        }
        const WorldObject& o = *world.objects[static_cast<std::size_t>(object)];
        if (o.plain()) {  // no surface point needed
          out.image.radiance_W_cm2_sr[i] = o.plain_radiance(part);
          return;
        }
        const Vec3 point_body = o.seen.body_to_frame.transpose() * (range_m * d - o.seen.position_m);
        out.image.radiance_W_cm2_sr[i] = o.radiance_at(part, point_body, o.direction_to_body(normal_frame), facet);
      },
      threads, extended);
  out.rays = count;

  // Silhouette edges: a sample whose hit differs from a 4-neighbour's takes
  // the mean of s x s sub-samples over its footprint. A straight edge that
  // crosses a footprint separates its centre from a 4-neighbour's, so every
  // sample an edge crosses is refined, and an edge pixel's mean coverage is
  // that of (samples_per_pixel s)^2 samples (spec 5.2, eqs. 13-14).
  const std::int64_t s = world.fidelity().edge_supersampling;
  if (s > 1) {
    const auto differs = [&](std::size_t a, std::size_t b) {
      return out.hits[a].object_id != out.hits[b].object_id || out.hits[a].part != out.hits[b].part;
    };
    // The edge samples in grid order, found row block by row block.
    constexpr std::int64_t rows_per_thread = 64;
    std::vector<std::vector<std::size_t>> found(parallel_range_count(h, threads, rows_per_thread));
    parallel_indexed_ranges(h, threads, [&](unsigned t, std::int64_t r0, std::int64_t r1) {
      std::vector<std::size_t>& mine = found[t];
      for (std::int64_t r = r0; r < r1; ++r)
        for (std::int64_t c = 0; c < w; ++c) {
          const auto i = static_cast<std::size_t>(r * w + c);
          if ((c > 0 && differs(i, i - 1)) || (c + 1 < w && differs(i, i + 1)) ||
              (r > 0 && differs(i, i - static_cast<std::size_t>(w))) ||
              (r + 1 < h && differs(i, i + static_cast<std::size_t>(w))))
            mine.push_back(i);
        }
    }, rows_per_thread);
    std::vector<std::size_t> edges;
    for (const auto& f : found) edges.insert(edges.end(), f.begin(), f.end());
    const auto sub = static_cast<std::size_t>(s * s);
    constexpr std::size_t edges_per_batch = 4096;  // bounds the batch's rays and hits
    std::vector<Vec3> directions;
    std::vector<geometry::Hit> sub_hits;
    for (std::size_t first = 0; first < edges.size(); first += edges_per_batch) {
      const std::size_t last = std::min(edges.size(), first + edges_per_batch);
      directions.clear();
      for (std::size_t k = first; k < last; ++k) {
        const auto c = static_cast<double>(static_cast<std::int64_t>(edges[k]) % w);
        const auto r = static_cast<double>(static_cast<std::int64_t>(edges[k]) / w);
        for (std::int64_t j = 0; j < s; ++j)
          for (std::int64_t i = 0; i < s; ++i)
            directions.push_back(world.sample_direction(c + (static_cast<double>(i) + 0.5) / static_cast<double>(s) - 0.5,
                                                        r + (static_cast<double>(j) + 0.5) / static_cast<double>(s) - 0.5));
      }
      world.caster.cast(directions, sub_hits, threads, extended);
      parallel_ranges(
          static_cast<std::int64_t>(last - first), threads,
          [&](std::int64_t begin, std::int64_t end) {
            for (std::int64_t k = begin; k < end; ++k) {
              double sum = 0;
              for (std::size_t m = 0; m < sub; ++m) {
                const geometry::Hit& hit = sub_hits[static_cast<std::size_t>(k) * sub + m];
                if (hit.object_id < 0) {
                  sum += sky_varies ? world.sky_radiance(directions[static_cast<std::size_t>(k) * sub + m]) : background;
                  continue;
                }
                const WorldObject& o = *world.objects[static_cast<std::size_t>(hit.object_id)];
                sum += o.radiance_at(hit.part, hit.point_body_m, o.direction_to_body(hit.normal_frame), hit.facet);
              }
              out.image.radiance_W_cm2_sr[edges[first + static_cast<std::size_t>(k)]] = sum / static_cast<double>(sub);
            }
          },
          64);
    }
    out.rays += edges.size() * sub;
  }
  out.point_sources_s = seconds(t0, t1);
  out.ray_casting_s = seconds(t1, clock::now());
  return out;
}

}  // namespace eoir::scene
