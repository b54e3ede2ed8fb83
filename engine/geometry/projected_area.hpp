// Projected area A*_T of an object as seen from a direction (spec eq. 58):
// the integral of cos(theta) over the surface facing the observer.
#pragma once
#include "geometry/scene_geometry.hpp"

namespace eoir::geometry {

// toward_observer_body: unit vector from the object toward the observer, in
// the body frame. Exact for a single sphere, oblate, box, plate or cylinder;
// otherwise the sum over patches of max(0, n.v) dA (self-shadowing between
// parts of a composite is not removed).
double projected_area_m2(const std::vector<ShapePart>& parts, const Tessellation& tessellation,
                         const Vec3& toward_observer_body);
// The exact projected area of one part, or -1 where the shape has no closed
// form here (cone, coupler).
double analytic_projected_area_m2(const ShapePart& part, const Vec3& toward_observer_body);

}  // namespace eoir::geometry
