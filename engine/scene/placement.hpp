// One object of the modeled universe placed relative to an observer at an
// instant (DESIGN.md section 1, step 1): its shape parts, body frame and
// position in double precision, and the surface it is made of. Shared by
// the scene generator and the target metrics, so both see the same world.
#pragma once
#include <optional>

#include "geometry/scene_geometry.hpp"
#include "scene/frame.hpp"
#include "universe/universe.hpp"

namespace eoir::scene {

struct Placement {
  geometry::PlacedObject placed;  // position relative to the observer, J2000 axes
  FrameObject surface;            // name, kind flags, surface properties
  double range_m = 0;             // observer to body origin
  double bounding_radius_m = 0;   // sphere about the body origin enclosing every part
};

// The shape parts of an object in its body frame (composites flattened).
std::vector<geometry::ShapePart> shape_parts(const universe::Object& o);

// nullopt for objects that image nothing (sensors, the star field, shape
// "none") and for objects the host has not placed yet. The tessellation is
// left empty (see tessellate_placement) so that culled objects cost nothing.
std::optional<Placement> place_object(const universe::Universe& universe, const universe::Object& o,
                                      const EngineTime& t, const geometry::Vec3& observer_position_m,
                                      std::int32_t object_id);
void tessellate_placement(const universe::Object& o, Placement& placement);

// Band-integrated irradiance at the observer of an object seen as a point
// (spec 4.1.6.1; the tessellation sum of ERRATA eq. 11, sum of L dOmega over
// the visible patches): for a single uniform shape, L A* / R^2 with the
// projected area A* of eq. 58, exact for analytic shapes; for composites and
// varying surfaces the patch sum (parts shadowing parts are not removed).
// W/cm^2.
double point_irradiance_W_cm2(const Placement& placement, const SpectralView& view);
// A* / R^2, the target solid angle of eq. 58 (sr).
double projected_solid_angle_sr(const Placement& placement);

}  // namespace eoir::scene
