// The interface between the scene generator and the sensor model (spec 4.1.1,
// 4.1.6.1): the effective radiance of every angular sample of the sensor's
// grid and the list of point sources kept apart from it. The scene generator
// writes it; the sensor model reads nothing else of the scene.
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/sample_grid.hpp"

namespace eoir::radiometry {

// An object smaller than a scene sample (spec 4.1.6.1), kept apart from the
// sample grid at its exact focal-plane position. A source moving during the
// integration time draws a streak: its energy spread uniformly along the
// segment from (column, row) - streak / 2 to (column, row) + streak / 2.
struct PointSource {
  std::int32_t object_id = -1;  // the world's object, or -1 for a star
  std::int32_t star = -1;       // index of a star in the world's sky, or -1
  double column = 0, row = 0;   // fractional sample coordinates in the full grid, at the frame time
  double irradiance_W_cm2 = 0;  // band-integrated at the aperture (eq. 52)
  // Displacement over the integration time (end minus start), in samples: the
  // streak is centred on (column, row); 0, 0 for a source at rest.
  double streak_columns = 0, streak_rows = 0;
};

struct RadianceImage {
  geometry::SampleGrid grid;
  std::vector<double> radiance_W_cm2_sr;  // effective radiance (eq. 48) per sample, full grid incl. guard, row-major
  std::vector<PointSource> point_sources;  // inside the field of view
};

}  // namespace eoir::radiometry
