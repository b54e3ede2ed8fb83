// The shadow an object casts by its parts (issue 22 item 3; spec 4.1.5.3's
// eclipse test made exact for vehicles): whether the ray from a point toward
// the Sun's centre meets any part of a placed object. 0 or 1, no penumbra:
// the Sun's 0.5 deg disc is not resolved against such small occulters.
#pragma once
#include "geometry/scene_geometry.hpp"

namespace eoir::geometry {

// True when the ray point_m + t u (u unit, observer frame, 0 < t < max_range_m)
// meets a part of `object` (each part intersected analytically in double, in
// its own frame, as the ray caster does). The sphere of bounding_radius_m
// about the object's origin is the cheap reject.
bool parts_block_ray(const PlacedObject& object, double bounding_radius_m, const Vec3& point_m, const Vec3& u,
                     double max_range_m);

}  // namespace eoir::geometry
