#include "scene/motion_substeps.hpp"

#include <chrono>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace eoir::scene {

std::vector<std::shared_ptr<const World>> substep_worlds(const World& world, const universe::Universe& universe,
                                                         const universe::Library& library,
                                                         const universe::Object& sensor, std::int64_t substeps,
                                                         WorldCache* cache) {
  std::vector<std::shared_ptr<const World>> out;
  if (substeps <= 1) return out;
  std::set<std::string> point_sources;
  for (const auto& o : world.objects)
    if (o->imaging == Imaging::point_source) point_sources.insert(o->name);
  const double n = static_cast<double>(substeps);
  const double t_i = world.view.integration_time_s;
  for (std::int64_t k = 0; k < substeps; ++k) {
    const double offset_s = ((static_cast<double>(k) + 0.5) / n - 0.5) * t_i;
    // (odd N: the middle sub-step is the frame time, whose classes are the
    // frame's own, so its world is the frame's: null here)
    out.push_back(offset_s == 0.0 ? nullptr
                                  : build_world(universe, library, world.time.plus_seconds(offset_s), sensor,
                                                world.view, cache, &point_sources));
  }
  return out;
}

SceneImage generate_moving_scene(const World& world, const std::vector<std::shared_ptr<const World>>& substeps,
                                 unsigned threads, SceneImage storage) {
  SceneImage out = generate_scene(world, threads, std::move(storage));
  if (substeps.empty()) return out;
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  std::vector<double> sum(out.image.radiance_W_cm2_sr.size(), 0.0);
  SceneImage sub;
  std::size_t rays = out.rays;
  for (const auto& w : substeps) {
    const std::vector<double>* radiance = &out.image.radiance_W_cm2_sr;
    if (w) {
      sub = generate_scene(*w, threads, std::move(sub));
      rays += sub.rays;
      radiance = &sub.image.radiance_W_cm2_sr;
    }
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += (*radiance)[i];
  }
  const double inverse = 1.0 / static_cast<double>(substeps.size());
  for (std::size_t i = 0; i < sum.size(); ++i) out.image.radiance_W_cm2_sr[i] = sum[i] * inverse;
  out.rays = rays;
  out.ray_casting_s += std::chrono::duration<double>(clock::now() - t0).count();
  return out;
}

SceneRows generate_moving_scene_rows(const World& world, const std::vector<std::shared_ptr<const World>>& substeps,
                                     std::int64_t begin, std::int64_t end, unsigned threads, SceneRows storage) {
  SceneRows out = generate_scene_rows(world, begin, end, threads, std::move(storage));
  if (substeps.empty()) return out;
  std::vector<double> sum(out.radiance_W_cm2_sr.size(), 0.0);
  SceneRows sub;
  for (const auto& w : substeps) {
    const std::vector<double>* radiance = &out.radiance_W_cm2_sr;
    if (w) {
      sub = generate_scene_rows(*w, begin, end, threads, std::move(sub));
      out.rays += sub.rays;
      radiance = &sub.radiance_W_cm2_sr;
    }
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += (*radiance)[i];
  }
  const double inverse = 1.0 / static_cast<double>(substeps.size());
  for (std::size_t i = 0; i < sum.size(); ++i) out.radiance_W_cm2_sr[i] = sum[i] * inverse;
  return out;
}

}  // namespace eoir::scene
