// Internal to the geometry module: the patch rule of tessellation.cpp on a part
// whose point is in the part frame (spec 4.1.5.2).
#pragma once
#include "geometry/scene_geometry.hpp"

namespace eoir::geometry {

// Patch index (into t.patches) containing p_part_m on part `part`; normal_part
// (the seen side's outward normal, part frame) picks a plate's face. -1 when
// the part has no patches.
std::int32_t patch_in_part(const Tessellation& t, std::int32_t part, const ShapeGeom& g, const Vec3& p_part_m,
                           const Vec3& normal_part);

}  // namespace eoir::geometry
