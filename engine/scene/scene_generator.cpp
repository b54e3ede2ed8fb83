#include "scene/scene_generator.hpp"

#include <chrono>
#include <utility>

namespace eoir::scene {

SceneImage generate_scene(const World& world, unsigned threads, SceneImage storage) {
  using clock = std::chrono::steady_clock;
  const auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  const auto t0 = clock::now();
  SceneImage out;
  const geometry::SampleGrid& grid = world.grid();
  out.image.grid = grid;
  const Mat3 j2000_to_body = world.observer.body_to_j2000.transpose();

  // Distant area sources (4.1.6.1) at their exact positions, where they lie
  // inside the field of view and the line of sight to them is clear.
  for (const auto& o : world.objects) {
    if (o->imaging != Imaging::point_source) continue;
    double c = 0, r = 0;
    if (!grid.sample_of(j2000_to_body * o->placed.position_m, c, r) || !grid.in_field(c, r, 1e-4)) continue;
    const geometry::RayQuery others{geometry::ray_mask_all, o->id};
    if (world.caster.occluded(o->placed.position_m / o->range_m, o->range_m, others)) continue;
    out.image.point_sources.push_back(
        radiometry::PointSource{o->id, -1, c, r, o->point_irradiance_W_cm2(), o->streak_columns, o->streak_rows});
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
  const double sky_radiance = world.sky.background_radiance_W_cm2_sr;
  const auto direction = [&](std::int64_t c, std::int64_t r) { return world.sample_direction(c, r); };
  world.caster.cast_grid(
      w, h, direction,
      [&](std::int64_t c, std::int64_t r, std::int32_t object, std::int32_t part, double range_m, const Vec3& d) {
        const auto i = static_cast<std::size_t>(r * w + c);
        out.hits[i] = SampleHit{object, part};
        if (object < 0) {
          out.image.radiance_W_cm2_sr[i] = sky_radiance;  // the background light (spec 4.1.4), 0 without a sky
          return;
        }
        const WorldObject& o = *world.objects[static_cast<std::size_t>(object)];
        if (o.surface->plain()) {
          out.image.radiance_W_cm2_sr[i] = o.surface->part_radiance(part);
          return;
        }
        const Vec3 point_body = o.placed.body_to_frame.transpose() * (range_m * d - o.placed.position_m);
        out.image.radiance_W_cm2_sr[i] = o.radiance_at(part, point_body);
      },
      threads, geometry::RayQuery{geometry::ray_mask_extended, -1});
  out.point_sources_s = seconds(t0, t1);
  out.ray_casting_s = seconds(t1, clock::now());
  out.rays = count;
  return out;
}

}  // namespace eoir::scene
