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
// irradiance below a sample), so no light is counted twice or lost. The
// scene is made whole (a frame in strips takes one sub-step).
#pragma once
#include <cstdint>

#include "scene/scene_generator.hpp"
#include "scene/world.hpp"
#include "universe/universe.hpp"

namespace eoir::scene {

// The scene of `world` (the frame time's, for `sensor` of `universe`) with
// `substeps` sub-steps (1: generate_scene(world) itself, spec 5.1
// assumption 6). The sub-steps' world builds and scenes count in
// ray_casting_s and rays. threads, storage: as generate_scene.
SceneImage generate_moving_scene(const World& world, const universe::Universe& universe,
                                 const universe::Library& library, const universe::Object& sensor,
                                 std::int64_t substeps, WorldCache* cache, unsigned threads,
                                 SceneImage storage = {});

}  // namespace eoir::scene
