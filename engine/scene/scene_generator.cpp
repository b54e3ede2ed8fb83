#include "scene/scene_generator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/parallel_ranges.hpp"
#include "scene/apparent_grid.hpp"

namespace eoir::scene {
namespace {

// Objects imaged as Imaging::small_extended are ray-cast as any extended
// object (their samples' hits, picks), but a sample is too coarse for them:
// every sample they reach takes its light from a window of at least 2 x 2
// rays per sample across them (WorldObject::window). The rays that meet the
// object bring their radiance times their solid angle (W cm^-2) to the four
// samples about them (bilinear weights, summing to 1), as radiance over a
// sample's solid angle (the sensor's IFOV over samples_per_pixel^2, eqs.
// 13-14), and cover that share of the sample; the rest of the sample sees
// what lies behind the object (its centre ray cast past it); samples inside
// a single part keep their own value. An object of
// several parts brings its patches' radiances scaled to its point
// irradiance, so that the image holds its detailed sum (ERRATA eq. 11) at
// every range, as its point source does once it is smaller than a sample;
// one part, convex, its radiance at each ray's point as the scene mode has
// it, the window's solid angle scaled to its projected area (eq. 58), and
// below kSmallBlendSamples samples across drawn toward its point irradiance.
constexpr double kSmallBlendSamples = 4.0;

// Rows [begin, end) of the grid are written; radiance and hits hold rows
// [lo, hi) (at least one beyond [begin, end) on each side inside the grid).
void add_small_objects(const World& world, std::vector<double>& radiance, const std::vector<SampleHit>& hits,
                       std::int64_t lo, std::int64_t hi, std::int64_t begin, std::int64_t end, unsigned threads) {
  const geometry::SampleGrid& grid = world.grid();
  const std::int64_t w = grid.width();
  const double n = static_cast<double>(grid.per_pixel);
  const double sample_sr = (2.0 * std::atan(grid.pitch_x_cm / (2.0 * grid.focal_length_cm)) / n) *
                           (2.0 * std::atan(grid.pitch_y_cm / (2.0 * grid.focal_length_cm)) / n);
  const Mat3 to_body = world.observer.body_to_j2000.transpose();
  for (const auto& o : world.objects) {
    if (o->imaging != Imaging::small_extended) continue;
    double cc = 0, rc = 0;
    if (!grid.sample_of(to_body * o->seen.position_m, cc, rc)) continue;
    const double across =
        2.0 * std::asin(std::min(1.0, o->bounding_radius_m / o->seen.position_m.norm())) / grid.sample_angle_rad();
    const auto rays = std::max<std::int64_t>(kVisibleWindowRays, static_cast<std::int64_t>(std::ceil(2.0 * across)));
    VisibleWindow own;
    if (rays > kVisibleWindowRays) own = o->window(rays, threads);
    const VisibleWindow& window = rays > kVisibleWindowRays ? own : o->visible_window();
    const bool composite = o->placed.parts.size() > 1;
    std::vector<double> L(window.rays.size());
    double sum = 0, window_sr = 0;
    for (std::size_t k = 0; k < L.size(); ++k) {
      const VisibleWindow::Ray& ray = window.rays[k];
      L[k] = composite ? o->patch_radiance(ray.patch)
                       : o->radiance_at(ray.part, ray.point_body_m, ray.normal_body, ray.facet);
      sum += L[k] * ray.solid_angle_sr;
      window_sr += ray.solid_angle_sr;
    }
    // One part: its solid angle is A* / R^2 (eq. 58, exact for every single
    // shape), its light drawn toward its point irradiance as it nears a
    // sample's size (continuous with its point source).
    const double to_point = sum > 0 ? o->point_irradiance_W_cm2() / sum : 0.0;
    const double to_area = window_sr > 0 ? o->projected_area_m2() / (o->range_m * o->range_m) / window_sr : 0.0;
    const double t = std::clamp((across - 1.0) / (kSmallBlendSamples - 1.0), 0.0, 1.0);
    const double scale = composite ? to_point : (1.0 - t) * to_point + t * to_area;
    // The box of samples it may reach.
    const auto reach = static_cast<std::int64_t>(std::ceil(0.5 * across)) + 2;
    const auto ic = static_cast<std::int64_t>(std::lround(cc)), ir = static_cast<std::int64_t>(std::lround(rc));
    const std::int64_t c0 = std::max<std::int64_t>(0, ic - reach), c1 = std::min<std::int64_t>(w, ic + reach + 1);
    const std::int64_t r0 = std::max<std::int64_t>(0, ir - reach), r1 = std::min<std::int64_t>(grid.height(), ir + reach + 1);
    if (c1 <= c0 || r1 <= r0 || r1 <= begin || r0 >= end) continue;
    const std::int64_t bw = c1 - c0;
    std::vector<double> energy(static_cast<std::size_t>(bw * (r1 - r0)), 0.0), cover(energy.size(), 0.0);
    const auto add = [&](std::int64_t c, std::int64_t r, double weight, double E, double omega) {
      if (c < c0 || c >= c1 || r < r0 || r >= r1) return;
      const auto i = static_cast<std::size_t>((r - r0) * bw + (c - c0));
      energy[i] += weight * E;
      cover[i] += weight * omega;
    };
    for (std::size_t k = 0; k < L.size(); ++k) {
      const VisibleWindow::Ray& ray = window.rays[k];
      double c = 0, r = 0;
      if (!grid.sample_of(to_body * ray.direction, c, r)) continue;
      const double E = L[k] * ray.solid_angle_sr * scale, omega = ray.solid_angle_sr;
      const double fc = c - std::floor(c), fr = r - std::floor(r);
      const auto jc = static_cast<std::int64_t>(std::floor(c)), jr = static_cast<std::int64_t>(std::floor(r));
      add(jc, jr, (1 - fc) * (1 - fr), E, omega);
      add(jc + 1, jr, fc * (1 - fr), E, omega);
      add(jc, jr + 1, (1 - fc) * fr, E, omega);
      add(jc + 1, jr + 1, fc * fr, E, omega);
    }
    // The samples it reaches or whose centre ray ends on it, seen past it,
    // but for those inside it (theirs and their 4-neighbours' centre rays
    // end on it): there a single part keeps its own value (the one the
    // sample's pick gives), a composite (whose parts meet there) takes its
    // window's, with nothing behind.
    const auto on = [&](std::int64_t c, std::int64_t r) {
      return c >= 0 && c < w && r >= lo && r < hi && hits[static_cast<std::size_t>((r - lo) * w + c)].object_id == o->id;
    };
    std::vector<std::size_t> box;
    std::vector<Vec3> directions;
    for (std::int64_t r = std::max(r0, begin); r < std::min(r1, end); ++r)
      for (std::int64_t c = c0; c < c1; ++c) {
        const auto i = static_cast<std::size_t>((r - r0) * bw + (c - c0));
        if (on(c, r) && on(c - 1, r) && on(c + 1, r) && on(c, r - 1) && on(c, r + 1)) {
          // (a composite's parts meet inside it: its window there, nothing behind)
          if (composite) radiance[static_cast<std::size_t>((r - lo) * w + c)] = energy[i] / sample_sr;
          continue;
        }
        if (cover[i] > 0 || on(c, r)) {
          box.push_back(i);
          directions.push_back(world.sample_direction(static_cast<double>(c), static_cast<double>(r)));
        }
      }
    std::vector<geometry::Hit> behind;
    world.caster.cast(directions, behind, threads, geometry::RayQuery{geometry::ray_mask_extended, o->id});
    for (std::size_t k = 0; k < box.size(); ++k) {
      const geometry::Hit& hit = behind[k];
      double L_behind = 0;
      if (hit.object_id < 0) {
        L_behind = world.sky_radiance(directions[k]);
      } else {
        const WorldObject& x = *world.objects[static_cast<std::size_t>(hit.object_id)];
        L_behind = x.radiance_at(hit.part, hit.point_body_m, x.direction_to_body(hit.normal_frame), hit.facet);
      }
      const std::size_t i = box[k];
      const std::int64_t c = c0 + static_cast<std::int64_t>(i) % bw, r = r0 + static_cast<std::int64_t>(i) / bw;
      radiance[static_cast<std::size_t>((r - lo) * w + c)] =
          energy[i] / sample_sr + (1.0 - std::min(1.0, cover[i] / sample_sr)) * L_behind;
    }
  }
}

// The point sources of the field (spec 4.1.6.1): distant area sources at
// their exact positions (where they appear: scene/apparent_grid.hpp), where
// they lie inside the field of view and the (geometric) line of sight to them
// is clear, then the catalogue stars, placed and culled with the world's sky.
std::vector<radiometry::PointSource> field_point_sources(const World& world) {
  std::vector<radiometry::PointSource> out;
  const geometry::SampleGrid& grid = world.grid();
  const ApparentGrid apparent(world);
  for (const auto& o : world.objects) {
    if (o->imaging != Imaging::point_source) continue;
    GridPlace p;
    if (!apparent.object(*o, p) || !grid.in_field(p.column, p.row, 1e-4)) continue;
    const geometry::RayQuery others{geometry::ray_mask_all, o->id};
    if (world.caster.occluded(o->seen.position_m / o->range_m, o->range_m, others)) continue;
    out.push_back(radiometry::PointSource{o->id, -1, p.column, p.row, o->point_irradiance_W_cm2(), p.streak_columns,
                                          p.streak_rows});
  }
  for (std::size_t k = 0; k < world.sky.stars.size(); ++k) {
    const WorldStar& s = world.sky.stars[k];
    out.push_back(radiometry::PointSource{-1, static_cast<std::int32_t>(k), s.column, s.row, s.irradiance_W_cm2,
                                          s.streak_columns, s.streak_rows});
  }
  return out;
}

// Rows [begin, end) of the grid, ray-cast, shaded, their silhouette edges
// refined and small objects drawn, into radiance and hits, which hold rows
// [lo, hi): begin - 1 and end too where the grid has them (the neighbours an
// edge and a small object are found with). Returns the rays cast. Every
// value is the one the whole grid's generation gives (rows of the sky's
// coarse grid and the ray caster's tiles are the grid's own).
std::size_t shade_rows(const World& world, std::int64_t lo, std::int64_t hi, std::int64_t begin, std::int64_t end,
                       std::vector<double>& radiance, std::vector<SampleHit>& hits, unsigned threads) {
  const geometry::SampleGrid& grid = world.grid();
  // Ray-cast the sample grid (spec 4.1.3) against the objects imaged as
  // extended sources and shade only what is hit (WorldObject::radiance_at).
  const std::int64_t w = grid.width(), h = grid.height();
  const std::size_t count = static_cast<std::size_t>(w * (hi - lo));
  hits.resize(count);  // cast_grid emits every sample once
  radiance.resize(count);
  // (r: the grid's row; cast_grid's rows count from lo)
  const auto direction = [&](std::int64_t c, std::int64_t r) { return world.sample_direction(c, r); };
  // The directions of rows [lo, hi) from tangents made once per column and
  // row (RayCaster::TangentGrid: the observer's axes times
  // SampleGrid::direction_of_tangents, sample_direction's value).
  std::vector<double> tan_x(static_cast<std::size_t>(w)), tan_y(static_cast<std::size_t>(hi - lo));
  for (std::int64_t c = 0; c < w; ++c) tan_x[static_cast<std::size_t>(c)] = grid.tan_x(static_cast<double>(c));
  for (std::int64_t r = lo; r < hi; ++r) tan_y[static_cast<std::size_t>(r - lo)] = grid.tan_y(static_cast<double>(r));
  const bool sky_varies = world.atmosphere.sky != nullptr;  // under the atmosphere, with the line of sight
  const double background = world.sky.background_radiance_W_cm2_sr;
  // The sky under the atmosphere on a coarse grid (every kSkyStep-th
  // sample): a sample that meets nothing takes the bilinear value of its
  // cell where the cell's corners agree within kSkyAgreement (the sky is
  // smooth there, tabulated itself on degree-wide cells), else its own
  // lookup (the limb's haze, the horizon).
  constexpr std::int64_t kSkyStep = 8;
  constexpr double kSkyAgreement = 1e-3;
  // The coarse grid's rows j0 .. j0 + gh - 1 about rows [lo, hi).
  const std::int64_t gw = (w + kSkyStep - 1) / kSkyStep + 1, j0 = lo / kSkyStep, gh = (hi - 1) / kSkyStep + 2 - j0;
  std::vector<double> sky_grid;
  if (sky_varies) {
    sky_grid.resize(static_cast<std::size_t>(gw * gh));
    parallel_ranges(
        gh, threads,
        [&](std::int64_t a, std::int64_t b) {
          for (std::int64_t j = a; j < b; ++j)
            for (std::int64_t i = 0; i < gw; ++i)
              sky_grid[static_cast<std::size_t>(j * gw + i)] = world.sky_radiance(
                  direction(std::min(i * kSkyStep, w - 1), std::min((j0 + j) * kSkyStep, h - 1)));
        },
        4);
  }
  const auto sky_at = [&](std::int64_t c, std::int64_t r, const Vec3& d) {
    const std::int64_t i = c / kSkyStep, j = r / kSkyStep;
    const double* g0 = &sky_grid[static_cast<std::size_t>((j - j0) * gw + i)];
    const double* g1 = g0 + gw;
    const double least = std::min({g0[0], g0[1], g1[0], g1[1]}), most = std::max({g0[0], g0[1], g1[0], g1[1]});
    if (most - least > kSkyAgreement * most) return world.sky_radiance(d.squaredNorm() > 0 ? d : direction(c, r));
    // (the last cell of a row or column may be narrower)
    const double cw = static_cast<double>(std::min((i + 1) * kSkyStep, w - 1) - i * kSkyStep);
    const double ch = static_cast<double>(std::min((j + 1) * kSkyStep, h - 1) - j * kSkyStep);
    const double fx = cw > 0 ? static_cast<double>(c - i * kSkyStep) / cw : 0.0;
    const double fy = ch > 0 ? static_cast<double>(r - j * kSkyStep) / ch : 0.0;
    return (1 - fy) * ((1 - fx) * g0[0] + fx * g0[1]) + fy * ((1 - fx) * g1[0] + fx * g1[1]);
  };
  const geometry::RayQuery extended{geometry::ray_mask_extended, -1};
  world.caster.cast_grid_tiles(
      w, hi - lo, geometry::RayCaster::TangentGrid{tan_x.data(), tan_y.data(), world.observer.body_to_j2000},
      [&](const geometry::GridTile& tile) {
        // The shadow casters near the tile's points on each shaded object
        // (a tile sees one or a few): occultation tests for only those.
        thread_local std::vector<std::pair<std::int32_t, ShadowCasters>> near;
        std::size_t objects_near = 0;
        const auto casters_near = [&](std::int32_t object, const WorldObject& o) -> const ShadowCasters* {
          for (std::size_t k = 0; k < objects_near; ++k)
            if (near[k].first == object) return &near[k].second;
          Vec3 least = Vec3::Constant(std::numeric_limits<double>::infinity()), most = -least;
          for (int k = 0; k < tile.count; ++k)
            if (tile.object[k] == object) {
              const Vec3 p = tile.range_m[k] * tile.direction[k];
              least = least.cwiseMin(p);
              most = most.cwiseMax(p);
            }
          if (near.size() <= objects_near) near.resize(objects_near + 1);
          near[objects_near].first = object;
          o.shadow_casters_near(0.5 * (least + most), 0.5 * (most - least).norm(), near[objects_near].second);
          return &near[objects_near++].second;
        };
        // Samples shaded at their own points: their surface points first,
        // the map cells of all of them asked of the memory together (scattered
        // over maps of tens of MB, each would otherwise wait on its own).
        // (located an object's run of samples at a time: vector maths over the run)
        thread_local SurfacePoint points[geometry::GridTile::kMaxSamples];
        bool own_point[geometry::GridTile::kMaxSamples];
        SurfacePoint* run[geometry::GridTile::kMaxSamples];
        std::size_t run_length = 0;
        const WorldObject* run_object = nullptr;
        const auto locate_run = [&] {
          run_object->surface->locate(run, run_length);
          for (std::size_t j = 0; j < run_length; ++j) run_object->surface->prefetch_maps(*run[j]);
          run_length = 0;
        };
        for (int k = 0; k < tile.count; ++k) {
          own_point[k] = false;
          if (tile.object[k] < 0) continue;
          const WorldObject& o = *world.objects[static_cast<std::size_t>(tile.object[k])];
          if (o.plain() || !o.shades_each_sample()) continue;
          const Vec3 point_body =
              o.seen.body_to_frame.transpose() * (tile.range_m[k] * tile.direction[k] - o.seen.position_m);
          points[k] =
              o.surface->unlocated(SurfaceSite{tile.part[k], point_body, o.direction_to_body(tile.normal_frame[k])});
          own_point[k] = true;
          if (run_length > 0 && run_object != &o) locate_run();
          run_object = &o;
          run[run_length++] = &points[k];
        }
        if (run_length > 0) locate_run();
        for (int k = 0; k < tile.count; ++k)
          if (own_point[k]) world.objects[static_cast<std::size_t>(tile.object[k])]->surface->read_maps(points[k]);
        // Their radiance an object's run at a time (effective_radiances).
        double own_radiance[geometry::GridTile::kMaxSamples];
        for (int k = 0; k < tile.count;) {
          if (!own_point[k]) {
            ++k;
            continue;
          }
          const std::int32_t object = tile.object[k];
          const WorldObject& o = *world.objects[static_cast<std::size_t>(object)];
          int run_end = k;
          run_length = 0;
          while (run_end < tile.count && own_point[run_end] && tile.object[run_end] == object)
            run[run_length++] = &points[run_end++];
          o.effective_radiances(run, run_length, casters_near(object, o), own_radiance + k);
          k = run_end;
        }
        for (int k = 0; k < tile.count; ++k) {
          const std::int64_t c = tile.column[k], r = tile.row[k];
          const std::int32_t object = tile.object[k], part = tile.part[k];
          const Vec3& d = tile.direction[k];
          const auto i = static_cast<std::size_t>(r * w + c);
          hits[i] = SampleHit{object, part};
          if (object < 0) {
            // the background light (spec 4.1.4), or the sky's
            radiance[i] = sky_varies ? sky_at(c, r + lo, d) : background;
            continue;
          }
          const WorldObject& o = *world.objects[static_cast<std::size_t>(object)];
          if (o.plain()) {  // no surface point needed
            radiance[i] = o.plain_radiance(part);
            continue;
          }
          if (own_point[k]) {
            radiance[i] = own_radiance[k];
            continue;
          }
          const Vec3 point_body = o.seen.body_to_frame.transpose() * (tile.range_m[k] * d - o.seen.position_m);
          radiance[i] = o.radiance_at(part, point_body, o.direction_to_body(tile.normal_frame[k]), tile.facet[k]);
        }
      },
      threads, extended);
  std::size_t rays = count;

  // Silhouette edges: a sample whose hit differs from a 4-neighbour's takes
  // the mean of s x s sub-samples over its footprint. A straight edge that
  // crosses a footprint separates its centre from a 4-neighbour's, so every
  // sample an edge crosses is refined, and an edge pixel's mean coverage is
  // that of (samples_per_pixel s)^2 samples (spec 5.2, eqs. 13-14).
  const std::int64_t s = world.fidelity().edge_supersampling;
  if (s > 1) {
    const auto differs = [&](std::size_t a, std::size_t b) {
      return hits[a].object_id != hits[b].object_id || hits[a].part != hits[b].part;
    };
    // The edge samples in grid order, found row block by row block.
    constexpr std::int64_t rows_per_thread = 64;
    std::vector<std::vector<std::size_t>> found(parallel_range_count(end - begin, threads, rows_per_thread));
    parallel_indexed_ranges(end - begin, threads, [&](unsigned t, std::int64_t r0, std::int64_t r1) {
      std::vector<std::size_t>& mine = found[t];
      for (std::int64_t r = begin + r0; r < begin + r1; ++r)
        for (std::int64_t c = 0; c < w; ++c) {
          const auto i = static_cast<std::size_t>((r - lo) * w + c);
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
        const auto r = static_cast<double>(static_cast<std::int64_t>(edges[k]) / w + lo);
        for (std::int64_t j = 0; j < s; ++j)
          for (std::int64_t i = 0; i < s; ++i)
            directions.push_back(world.sample_direction(c + (static_cast<double>(i) + 0.5) / static_cast<double>(s) - 0.5,
                                                        r + (static_cast<double>(j) + 0.5) / static_cast<double>(s) - 0.5));
      }
      world.caster.cast(directions, sub_hits, threads, extended);
      parallel_ranges(
          static_cast<std::int64_t>(last - first), threads,
          [&](std::int64_t k0, std::int64_t k1) {
            for (std::int64_t k = k0; k < k1; ++k) {
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
              radiance[edges[first + static_cast<std::size_t>(k)]] = sum / static_cast<double>(sub);
            }
          },
          64);
    }
    rays += edges.size() * sub;
  }
  add_small_objects(world, radiance, hits, lo, hi, begin, end, threads);
  return rays;
}

}  // namespace

SceneImage generate_scene(const World& world, unsigned threads, SceneImage storage) {
  using clock = std::chrono::steady_clock;
  const auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  const auto t0 = clock::now();
  SceneImage out;
  out.image.grid = world.grid();
  out.image.point_sources = field_point_sources(world);
  const auto t1 = clock::now();
  // Ray-cast the sample grid (spec 4.1.3), every row at once.
  out.hits = std::move(storage.hits);
  out.image.radiance_W_cm2_sr = std::move(storage.image.radiance_W_cm2_sr);
  const std::int64_t h = world.grid().height();
  out.rays = shade_rows(world, 0, h, 0, h, out.image.radiance_W_cm2_sr, out.hits, threads);
  out.point_sources_s = seconds(t0, t1);
  out.ray_casting_s = seconds(t1, clock::now());
  return out;
}

SceneImage generate_point_sources(const World& world) {
  SceneImage out;
  out.image.grid = world.grid();
  out.image.point_sources = field_point_sources(world);
  return out;
}

SceneRows generate_scene_rows(const World& world, std::int64_t begin, std::int64_t end, unsigned threads,
                              SceneRows storage) {
  const geometry::SampleGrid& grid = world.grid();
  const std::int64_t w = grid.width(), h = grid.height();
  if (begin < 0 || end > h || begin >= end)
    throw Error(Status::out_of_range, "scene rows: [" + std::to_string(begin) + ", " + std::to_string(end) +
                                          ") not within the grid's " + std::to_string(h));
  SceneRows out = std::move(storage);
  out.first_row = begin;
  const std::int64_t lo = std::max<std::int64_t>(0, begin - 1), hi = std::min(h, end + 1);
  out.rays = shade_rows(world, lo, hi, begin, end, out.radiance_W_cm2_sr, out.hits, threads);
  // Only rows [begin, end) are kept.
  const auto skip = static_cast<std::ptrdiff_t>((begin - lo) * w), keep = static_cast<std::ptrdiff_t>((end - begin) * w);
  if (skip > 0) {
    std::move(out.radiance_W_cm2_sr.begin() + skip, out.radiance_W_cm2_sr.begin() + skip + keep,
              out.radiance_W_cm2_sr.begin());
    std::move(out.hits.begin() + skip, out.hits.begin() + skip + keep, out.hits.begin());
  }
  out.radiance_W_cm2_sr.resize(static_cast<std::size_t>(keep));
  out.hits.resize(static_cast<std::size_t>(keep));
  return out;
}

}  // namespace eoir::scene
