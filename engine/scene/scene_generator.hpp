// The synthetic scene generator (spec 4.1): images a world on its sample
// grid. Objects imaged as extended sources are ray-cast (spec 4.1.3) and
// shaded where the samples hit them (eq. 48 of eq. 4); distant area sources
// smaller than a sample (4.1.6.1) go to the point-source list where they lie
// inside the ideal field of view (5.2, 7.2.1) and no object hides them.
#pragma once
#include <cstdint>
#include <vector>

#include "radiometry/radiance_image.hpp"
#include "scene/world.hpp"

namespace eoir::scene {

// What one sample of the full grid ends on: object_id (-1 the sky) and shape
// part. Range, point and patch are recomputed for picks by casting that one
// ray again against the world.
struct SampleHit {
  std::int32_t object_id = -1;
  std::int32_t part = -1;
};

struct SceneImage {
  radiometry::RadianceImage image;  // the output to the sensor model (spec 4.1.1)
  std::vector<SampleHit> hits;      // per sample of the full grid, row-major
  double point_sources_s = 0;       // point-source placement, occlusion and irradiance
  double ray_casting_s = 0;         // sample rays with the per-sample radiance lookup
  std::size_t rays = 0;
};

// threads: 0 = all cores. `storage`: a finished scene whose sample buffers
// are reused (every sample is overwritten), so a frame touches no fresh
// memory (DESIGN.md 4).
SceneImage generate_scene(const World& world, unsigned threads, SceneImage storage = {});

// A frame made in strips (sensor/scene_convolution.hpp): its point sources
// alone, without sample buffers; then its sample rows strip by strip.
SceneImage generate_point_sources(const World& world);

// Rows [first_row, first_row + radiance.size() / grid width) of the full grid.
struct SceneRows {
  std::int64_t first_row = 0;
  std::vector<double> radiance_W_cm2_sr;
  std::vector<SampleHit> hits;
  std::size_t rays = 0;
};
// Rows [begin, end) of the full grid, each sample equal to generate_scene's
// (a strip reads its neighbour rows for silhouette edges and small objects).
// Throws Error(out_of_range) for rows outside the grid.
SceneRows generate_scene_rows(const World& world, std::int64_t begin, std::int64_t end, unsigned threads,
                              SceneRows storage = {});

}  // namespace eoir::scene
