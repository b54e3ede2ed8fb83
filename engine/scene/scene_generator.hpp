// The synthetic scene generator (spec 4.1): places the modeled universe
// relative to the sensor at one instant, splits it into resolved objects
// (ray-cast on the sample grid) and distant area sources smaller than a
// sample (point sources, spec 4.1.6.1), and shades what the samples hit.
#pragma once
#include "scene/frame.hpp"
#include "sensor/static_metrics.hpp"
#include "universe/universe.hpp"

namespace eoir::scene {

// Fills frame.{time, grid, spectral, body_to_j2000, boresight/up, objects,
// hits, scene_radiance, point_sources}. threads: 0 = all cores.
void generate_scene(const universe::Universe& universe, const EngineTime& t, const universe::Object& sensor,
                    const sensor::StaticMetrics& metrics, unsigned threads, Frame& frame);

}  // namespace eoir::scene
