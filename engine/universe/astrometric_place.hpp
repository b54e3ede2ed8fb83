// Astrometric places (issue 21 item 1): the direction in the frame of a star
// catalogue (ICRS) of something seen in an apparent direction, as a plate
// solution against the catalogue measures it. It undoes the last two steps
// of the apparent-place chain (universe/star_catalog.hpp: light deflection by
// the Sun, eraLdsun; aberration by the observer's barycentric velocity,
// eraAb) for one instant, by fixed-point iteration on that chain itself: for
// a star it gives the catalogue place moved by proper motion and parallax
// (SOFA's "astrometric place"); for an Earth satellite drawn at its geometric
// direction it gives that direction displaced by minus the annual aberration,
// as catalogue-reduced satellite observations have it.
#pragma once
#include "universe/star_catalog.hpp"

namespace eoir::universe {

// Unit ICRS direction whose apparent place (deflection and aberration of
// `context`) is the unit vector `apparent` (GCRS = J2000 axes). Converges to
// 1e-15 rad in at most four iterations (each step shrinks the error by about
// |v|/c ~ 1e-4). Throws out_of_range naming "apparent" for a non-finite or
// zero vector.
Vec3 astrometric_direction(const Vec3& apparent, const ApparentPlaceContext& context);

}  // namespace eoir::universe
