// A frame's sky in the catalogue's coordinates (issue 21 item 1). The image
// holds stars at their apparent places (sky.hpp) and the Moon and planets at
// theirs; a plate solution against a star catalogue absorbs the field's
// aberration and light deflection into its WCS. AstrometricFrame gives that
// WCS and the astrometric place (universe/astrometric_place.hpp) of any
// apparent direction, for the observer's barycentric state at the frame
// time. Refraction (observers inside the atmosphere) stays in the image:
// the WCS does not absorb it.
#pragma once
#include "scene/world.hpp"
#include "universe/star_catalog.hpp"

namespace eoir::scene {

// The astrometric TAN WCS of the sensor's pixels: the reference pixel is the
// image centre (the boresight).
struct AstrometricWcs {
  double ra_deg = 0, dec_deg = 0;  // ICRS of the image centre
  // d(xi, eta)/d(column, row) at the centre, degrees per sensor pixel:
  // {dxi/dcolumn, dxi/drow, deta/dcolumn, deta/drow}; xi toward east, eta
  // toward north in the tangent plane at (ra_deg, dec_deg); columns and rows
  // as images are stored (row 0 at the top).
  double cd_deg[4] = {0, 0, 0, 0};
};

class AstrometricFrame {
 public:
  explicit AstrometricFrame(const World& world);
  // Unit ICRS direction of something seen in the apparent direction d
  // (J2000 axes, any length) at the frame time.
  Vec3 astrometric(const Vec3& d) const;
  const AstrometricWcs& wcs() const { return wcs_; }
  const universe::ApparentPlaceContext& context() const { return context_; }

 private:
  universe::ApparentPlaceContext context_;
  AstrometricWcs wcs_;
};

}  // namespace eoir::scene
