// The geometric scene (spec 4.1.3, 4.1.5): objects made of analytic shape
// parts, placed relative to the observer in double precision (DESIGN.md
// section 3), each surface divided into patches dA, and the ray caster that
// finds the nearest surface along a direction.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "geometry/shape_intersect.hpp"
#include "universe/shapes.hpp"

namespace eoir::geometry {

using Mat3 = Eigen::Matrix3d;

// One simple shape inside an object (universe/shapes.hpp), decoded, at its
// offset and orientation in the object's body frame. Shapes: sphere [r],
// oblate [a, c] (ellipsoid, c along z), box [x, y, z], plate [x, y] (zero
// thickness, normal +z, seen from both sides), cylinder [r, length] (axis z,
// centred), cone [r_base, length] (base at z = -length/2, apex at
// +length/2), coupler [r_base, r_top, length] (frustum), none (never hit).
struct ShapePart {
  ShapeGeom geom;
  Vec3 offset_m = Vec3::Zero();                                     // part origin in body frame
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // part -> body
};
// Decodes a part of the universe (throws eoir::Error naming `field`).
ShapePart make_part(const universe::ShapePart& part, const std::string& field = "shape");

// A patch dA (spec 4.1.5.2): roughly equal-area piece of one part's surface.
struct Patch {
  std::int32_t part = 0;
  Vec3 centre_body_m = Vec3::Zero();
  Vec3 normal_body = Vec3::UnitZ();  // outward unit normal at the centre
  double area_m2 = 0.0;
};

// Patches of every part of one object, and the rule that maps a surface
// point to its patch.
struct Tessellation {
  std::vector<Patch> patches;
  // Per part: first patch index and parametrisation data (implementation's).
  std::vector<std::int32_t> first_patch;
  std::vector<std::vector<std::int32_t>> grid;
  double target_patch_size_m = 0.0;
};

// Divides every part into patches whose edge is about target_patch_size_m
// (sphere/ellipsoid: latitude bands with longitude cells of equal area; flat
// faces: rectangular grids; cylinders/cones/couplers: side grid + caps).
Tessellation tessellate(const std::vector<ShapePart>& parts, double target_patch_size_m);
// The patch containing `point_body_m` on part `part` (the point is on or very
// near that part's surface), the face of a two-sided plate picked by the
// seen side's outward normal (body frame; a hit's, which the ray caster
// gives: the side of a point on the plate is rounding). A plate's patches
// are its +z face grid followed by its -z face grid.
std::int32_t patch_at_facing(const Tessellation& t, const std::vector<ShapePart>& parts, std::int32_t part,
                             const Vec3& point_body_m, const Vec3& normal_body);
// The same where the ray caster named the hit's facet (a mesh triangle, Hit::
// facet): that triangle's patch without a search; facet -1: patch_at_facing.
std::int32_t patch_at_facet(const Tessellation& t, const std::vector<ShapePart>& parts, std::int32_t part,
                            std::int32_t facet, const Vec3& point_body_m, const Vec3& normal_body);

// Ray-mask bits of placed objects: sample rays of an image look for objects
// imaged as extended sources only; other queries see every object.
constexpr std::uint32_t ray_mask_extended = 1u;
constexpr std::uint32_t ray_mask_other = 2u;
constexpr std::uint32_t ray_mask_all = ~0u;

// One object placed in the observer-relative frame (axes of J2000, origin at
// the observer).
struct PlacedObject {
  std::int32_t object_id = 0;  // caller's identifier, returned in hits
  std::vector<ShapePart> parts;
  Vec3 position_m = Vec3::Zero();  // body origin relative to the observer (double)
  Mat3 body_to_frame = Mat3::Identity();
  std::uint32_t ray_mask = ray_mask_all;
};

// The nearest surface a ray meets, or the sky (object_id == -1).
struct Hit {
  std::int32_t object_id = -1;
  std::int32_t part = -1;
  std::int32_t facet = -1;            // a mesh part's triangle (its index in the part's group); -1 analytic
  double range_m = 0.0;               // along the ray; sky: see sky_range_m
  Vec3 point_body_m = Vec3::Zero();   // hit point in the object's body frame
  Vec3 normal_frame = Vec3::Zero();   // outward surface normal, observer frame
};

// 1000 times Neptune's orbital radius (30.07 AU), spec 4.1.3.
constexpr double sky_range_m = 1000.0 * 30.07 * 149597870700.0;

// Which objects a ray may meet: those whose ray_mask shares a bit with
// `mask`, except `skip_object`.
struct RayQuery {
  std::uint32_t mask = ray_mask_all;
  std::int32_t skip_object = -1;
};

// The samples of one tile of RayCaster::cast_grid_tiles (at most 8 x 8), in
// the order cast: sample i at (column[i], row[i]), as cast_grid's emit.
struct GridTile {
  static constexpr int kMaxSamples = 64;
  int count = 0;
  std::int64_t column[kMaxSamples], row[kMaxSamples];
  std::int32_t object[kMaxSamples], part[kMaxSamples], facet[kMaxSamples];
  double range_m[kMaxSamples];
  Vec3 direction[kMaxSamples], normal_frame[kMaxSamples];
};

// Ray casting with Embree 3: every part is an Embree user geometry whose
// intersection is computed analytically in double precision relative to the
// observer (rays start at the observer, the origin). Built once per world;
// every query is const and safe from many threads.
class RayCaster {
 public:
  RayCaster();
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Objects must outlive the caster (it keeps pointers).
  void build(const std::vector<const PlacedObject*>& objects);
  // The nearest hit along a unit direction (observer frame).
  Hit cast(const Vec3& direction, const RayQuery& query = {}) const;
  // Many directions on `threads` workers (0 = all cores), in coherent blocks.
  void cast(const std::vector<Vec3>& directions, std::vector<Hit>& hits, unsigned threads = 0,
            const RayQuery& query = {}) const;
  // The lean form for a frame's sample grid: ray (c, r) of width x height
  // goes along direction(c, r), a pinhole projection (the rays of a
  // rectangle of samples lie in the cone of its corner rays), and its nearest
  // surface goes to emit(c, r, object_id, part, facet, range_m, direction,
  // normal_frame) (object_id -1: the sky, with a zero normal, and a zero
  // direction where a tile near no object computed none): normal_frame is the hit's outward unit normal,
  // observer frame, the one cast() gives (the intersection computes it). Cast in tiles of 8 x 8 samples: a
  // tile whose bounding cone meets no part's bounding sphere is sky, one
  // whose nearby parts are all of one object is intersected with them
  // directly, the others go through Embree; the hits are those of cast().
  // Both callbacks are called from the worker threads, each sample once.
  void cast_grid(std::int64_t width, std::int64_t height,
                 const std::function<Vec3(std::int64_t, std::int64_t)>& direction,
                 const std::function<void(std::int64_t, std::int64_t, std::int32_t, std::int32_t, std::int32_t, double,
                                          const Vec3&, const Vec3&)>& emit,
                 unsigned threads = 0, const RayQuery& query = {}) const;
  // The same, a tile at a time: emit_tile(tile) once per tile, from the
  // worker threads, with the tile's samples (what emit would receive).
  void cast_grid_tiles(std::int64_t width, std::int64_t height,
                       const std::function<Vec3(std::int64_t, std::int64_t)>& direction,
                       const std::function<void(const GridTile&)>& emit_tile, unsigned threads = 0,
                       const RayQuery& query = {}) const;
  // The same for a pinhole grid given by its tangents: ray (c, r) along
  // body_to_frame * (tan_x[c], tan_y[r], 1) normalized (SampleGrid's
  // direction_of_tangents), computed in place rather than called per ray.
  struct TangentGrid {
    const double* tan_x = nullptr;
    const double* tan_y = nullptr;
    Mat3 body_to_frame = Mat3::Identity();
  };
  void cast_grid_tiles(std::int64_t width, std::int64_t height, const TangentGrid& directions,
                       const std::function<void(const GridTile&)>& emit_tile, unsigned threads = 0,
                       const RayQuery& query = {}) const;
  // True if any surface lies along `direction` closer than range_m.
  bool occluded(const Vec3& direction, double range_m, const RayQuery& query = {}) const;

 private:
  struct Impl;
  Impl* impl_;
  template <class Direction>
  void cast_tiles(std::int64_t width, std::int64_t height, const Direction& direction,
                  const std::function<void(const GridTile&)>& emit_tile, unsigned threads,
                  const RayQuery& query) const;
};

}  // namespace eoir::geometry
