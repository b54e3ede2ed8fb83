// Where point sources appear on the sample grid (spec 4.1.6.1) to an
// observer inside the Earth's atmosphere (spec 4.3.1.1; issue 20 item 6):
// raised toward the zenith by the refraction
// (WorldAtmosphere::apparent_direction) at the frame time, and at the start
// and the end of the integration for their streaks, with the observer's
// zenith of those instants. Stars are refracted by the whole refraction,
// objects by the share their distance gives (WorldObject::seen,
// refraction_fraction: nearly all of it beyond the atmosphere, about
// k D / 2 R_E for an aircraft D away), as the image's rays meet extended
// objects. Without the atmosphere, or from above it, every place is the
// geometric one, bit for bit. The truth's RA/Dec keep the geometric
// direction.
#pragma once
#include "scene/world.hpp"

namespace eoir::scene {

// A point source's place on the sample grid.
struct GridPlace {
  double column = 0, row = 0;                  // fractional sample coordinates at the frame time
  double streak_columns = 0, streak_rows = 0;  // displacement over the integration
};

class ApparentGrid {
 public:
  explicit ApparentGrid(const World& world);
  // The largest displacement (rad) of a source above the horizon: culling
  // margins.
  double max_refraction_rad() const;
  // A star in the fixed true direction d (unit, J2000 axes): false if it is
  // behind the sensor at the frame time.
  bool star(const Vec3& d, GridPlace& out) const;
  // An object imaged as a point source, with the streak the world gives it
  // (WorldObject::streak_columns, _rows) refracted at its ends: false if it
  // is behind the sensor at the frame time.
  bool object(const WorldObject& o, GridPlace& out) const;

 private:
  const World& world_;
  Mat3 to_body_, to_body_start_, to_body_end_;  // J2000 to the sensor's body axes at the frame time, start, end
  bool refracting_ = false;       // the atmosphere is on and the observer inside it
  WorldAtmosphere start_, end_;   // the world's, with the zenith at the start and the end of the integration
};

}  // namespace eoir::scene
