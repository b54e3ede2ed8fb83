// Resolved objects that move during the integration (beyond spec 5.1
// assumption 6, which holds the scene still over the integration and lets
// only point sources streak). With N motion sub-steps the effective-radiance
// image of eq. 49 is the mean of N scenes at the times
//   t_k = t + ((k + 1/2) / N - 1/2) t_i,   k = 0 .. N - 1,
// each rendered from a world of its own at t_k (the sensor's place and
// pointing, the objects' places and light then), so a resolved object smears
// along its path with its light shared among the sub-steps.
//
// The frame time's world keeps all else: the point sources (objects smaller
// than a sample and catalogue stars, each once, streaked over the whole
// integration), the hits that picks read, the per-frame truth. An object may
// change class within an integration only near the point/extended limit;
// its class at the frame time decides: an object the frame time's world
// images as a point source is one in every sub-step (its streak carries its
// light), and any other that a sub-step's world would image as a point
// source is imaged there as small_extended (its window drawn to its point
// irradiance below a sample), so no light is counted twice or lost. A frame
// made in strips averages each strip's rows over the sub-steps alike.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "scene/scene_generator.hpp"
#include "scene/world.hpp"
#include "universe/universe.hpp"

namespace eoir::scene {

// The worlds of the sub-steps of a frame at `world` (the frame time's, for
// `sensor` of `universe`): none for substeps <= 1 (spec 5.1 assumption 6);
// null where a sub-step falls on the frame time (its world is `world`).
std::vector<std::shared_ptr<const World>> substep_worlds(const World& world, const universe::Universe& universe,
                                                         const universe::Library& library,
                                                         const universe::Object& sensor, std::int64_t substeps,
                                                         WorldCache* cache);

// The scene of `world` with its radiance the mean over `substeps`
// (substep_worlds; none: generate_scene(world) itself). The sub-steps'
// scenes count in ray_casting_s and rays (the engine adds the world builds of
// substep_worlds there too). threads, storage: as generate_scene.
SceneImage generate_moving_scene(const World& world, const std::vector<std::shared_ptr<const World>>& substeps,
                                 unsigned threads, SceneImage storage = {});

// The same for rows [begin, end) of a frame made in strips (generate_scene_rows).
SceneRows generate_moving_scene_rows(const World& world, const std::vector<std::shared_ptr<const World>>& substeps,
                                     std::int64_t begin, std::int64_t end, unsigned threads, SceneRows storage = {});

}  // namespace eoir::scene
