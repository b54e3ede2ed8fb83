#include "scene/motion_substeps.hpp"

#include <chrono>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace eoir::scene {

SceneImage generate_moving_scene(const World& world, const universe::Universe& universe,
                                 const universe::Library& library, const universe::Object& sensor,
                                 std::int64_t substeps, WorldCache* cache, unsigned threads, SceneImage storage) {
  SceneImage out = generate_scene(world, threads, std::move(storage));
  if (substeps <= 1) return out;
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  std::set<std::string> point_sources;
  for (const auto& o : world.objects)
    if (o->imaging == Imaging::point_source) point_sources.insert(o->name);
  const double n = static_cast<double>(substeps);
  const double t_i = world.view.integration_time_s;
  std::vector<double> sum(out.image.radiance_W_cm2_sr.size(), 0.0);
  SceneImage sub;
  std::size_t rays = out.rays;
  for (std::int64_t k = 0; k < substeps; ++k) {
    const double offset_s = ((static_cast<double>(k) + 0.5) / n - 0.5) * t_i;
    const std::vector<double>* radiance = &out.image.radiance_W_cm2_sr;
    // (odd N: the middle sub-step is the frame time, whose classes are the
    // frame's own, so its scene is the frame's)
    if (offset_s != 0.0) {
      const auto w = build_world(universe, library, world.time.plus_seconds(offset_s), sensor, world.view, cache,
                                   &point_sources);
      sub = generate_scene(*w, threads, std::move(sub));
      rays += sub.rays;
      radiance = &sub.image.radiance_W_cm2_sr;
    }
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += (*radiance)[i];
  }
  const double inverse = 1.0 / n;
  for (std::size_t i = 0; i < sum.size(); ++i) out.image.radiance_W_cm2_sr[i] = sum[i] * inverse;
  out.rays = rays;
  out.ray_casting_s += std::chrono::duration<double>(clock::now() - t0).count();
  return out;
}

}  // namespace eoir::scene
