// Ray casting with Embree 3 user geometries (spec 4.1.3; DESIGN.md section 3).
//
// Embree only orders candidates: each object is one RTC_GEOMETRY_TYPE_USER
// geometry with one primitive per part; its float bounds (observer frame,
// origin at the observer) are padded well beyond float rounding, and the
// intersect callback solves the part analytically in double with the exact
// double direction. The per-ray context carries the best double range; a part
// wins only if its double t is smaller, so a 1 m satellite at 10 km beats the
// Earth behind it whatever float does. tfar is set to float(t) rounded up, so
// Embree never culls a candidate that could win in double.
//
// Observer inside an object: an object with any closed part containing the
// observer (exact test, shape_contains) is skipped entirely; elsewhere only
// outward-facing surfaces are hit (shape_intersect.hpp). An observer on a
// surface (within a relative 1e-9) counts as outside.
#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "core/error.hpp"
#include "core/parallel_ranges.hpp"
#include "geometry/embree_device.hpp"
#include "geometry/sample_grid.hpp"
#include "geometry/scene_geometry.hpp"
#include "geometry/shape_intersect.hpp"

namespace eoir::geometry {
namespace {

// One part, precomputed for the current observer.
struct PartData {
  ShapeGeom geom;
  Mat3 part_to_frame;      // rotation part -> observer frame
  Vec3 origin_part_m;      // the observer (frame origin) in the part frame
  Vec3 centre_frame_m;     // part origin in the observer frame
  double radius_m = 0;     // bounding radius about the part origin
};

struct ObjectData {
  const PlacedObject* object = nullptr;
  std::vector<PartData> parts;
  std::vector<unsigned> prim_part;  // Embree primID -> part index
  int index = 0;
  std::uint32_t mask = ray_mask_all;
  bool attached = false;  // in the Embree scene (not containing the observer, some part to hit)
};

// Extended context: Embree passes it to the callback (first member is the
// RTCIntersectContext, standard layout).
struct RayContext {
  RTCIntersectContext ctx;
  RayQuery query;
  Vec3 dir;
  double best_t = std::numeric_limits<double>::infinity();
  int object = -1;
  int part = -1;
  std::int32_t facet = -1;
  Vec3 normal_part = Vec3::Zero();
};

void bounds_callback(const RTCBoundsFunctionArguments* args) {
  const auto* od = static_cast<const ObjectData*>(args->geometryUserPtr);
  const PartData& p = od->parts[od->prim_part[args->primID]];
  const Vec3& c = p.centre_frame_m;
  // Pad for float rounding of the centre and of the ray direction (6e-8 rad).
  const double pad = 1e-5 * (c.norm() + p.radius_m) + 1e-6;
  const double r = p.radius_m + pad;
  RTCBounds* b = args->bounds_o;
  b->lower_x = static_cast<float>(c.x() - r);
  b->lower_y = static_cast<float>(c.y() - r);
  b->lower_z = static_cast<float>(c.z() - r);
  b->upper_x = static_cast<float>(c.x() + r);
  b->upper_y = static_cast<float>(c.y() + r);
  b->upper_z = static_cast<float>(c.z() + r);
}

// Whether a ray of `query` may meet the object.
bool admits(const RayQuery& query, const ObjectData& od) {
  return (query.mask & od.mask) != 0 && query.skip_object != od.object->object_id;
}

void intersect_callback(const RTCIntersectFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;
  const auto* od = static_cast<const ObjectData*>(args->geometryUserPtr);
  auto* rc = reinterpret_cast<RayContext*>(args->context);
  if (!admits(rc->query, *od)) return;
  const unsigned part_index = od->prim_part[args->primID];
  const PartData& p = od->parts[part_index];
  const Vec3 d = p.part_to_frame.transpose() * rc->dir;
  double t = 0;
  Vec3 n;
  std::int32_t facet = -1;
  if (!intersect_shape(p.geom, p.origin_part_m, d, 0.0, rc->best_t, t, n, &facet)) return;
  rc->best_t = t;
  rc->object = od->index;
  rc->part = static_cast<int>(part_index);
  rc->facet = facet;
  rc->normal_part = n;
  auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
  rh->ray.tfar = std::nextafter(static_cast<float>(t), std::numeric_limits<float>::infinity());
  rh->hit.geomID = args->geomID;
  rh->hit.primID = args->primID;
  rh->hit.instID[0] = args->context->instID[0];
  rh->hit.u = rh->hit.v = 0.0f;
  const Vec3 nf = p.part_to_frame * n;
  rh->hit.Ng_x = static_cast<float>(nf.x());
  rh->hit.Ng_y = static_cast<float>(nf.y());
  rh->hit.Ng_z = static_cast<float>(nf.z());
}

// Occlusion: the context carries the exact double direction and the range
// limit in best_t; any admitted hit closer than that occludes.
void occluded_callback(const RTCOccludedFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;
  const auto* od = static_cast<const ObjectData*>(args->geometryUserPtr);
  auto* rc = reinterpret_cast<RayContext*>(args->context);
  if (!admits(rc->query, *od)) return;
  const PartData& p = od->parts[od->prim_part[args->primID]];
  double t = 0;
  Vec3 n;
  if (intersect_shape(p.geom, p.origin_part_m, p.part_to_frame.transpose() * rc->dir, 0.0, rc->best_t, t, n)) {
    rc->object = od->index;
    reinterpret_cast<RTCRay*>(args->ray)->tfar = -std::numeric_limits<float>::infinity();
  }
}

}  // namespace

struct RayCaster::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<ObjectData> objects;

  void release() {
    if (scene) rtcReleaseScene(scene);
    scene = nullptr;
    objects.clear();
  }
};

RayCaster::RayCaster() : impl_(new Impl) {
  try {
    impl_->device = embree_device();
  } catch (...) {
    delete impl_;
    throw;
  }
}

RayCaster::~RayCaster() {
  impl_->release();
  delete impl_;
}

void RayCaster::build(const std::vector<const PlacedObject*>& objects) {
  impl_->release();
  RTCDevice device = impl_->device;
  RTCScene scene = rtcNewScene(device);
  check_embree(device, "rtcNewScene");
  impl_->scene = scene;
  rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);

  auto& data = impl_->objects;
  data.reserve(objects.size());  // stable addresses: Embree keeps pointers
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const PlacedObject& obj = *objects[k];
    ObjectData od;
    od.object = &obj;
    od.index = static_cast<int>(k);
    od.mask = obj.ray_mask;
    bool contains_observer = false;
    for (std::size_t i = 0; i < obj.parts.size(); ++i) {
      const ShapePart& sp = obj.parts[i];
      PartData pd;
      pd.geom = sp.geom;
      pd.part_to_frame = obj.body_to_frame * sp.orientation.toRotationMatrix();
      pd.centre_frame_m = obj.position_m + obj.body_to_frame * sp.offset_m;
      // Observer (origin) in the part frame, from body-frame quantities.
      const Vec3 observer_body = -(obj.body_to_frame.transpose() * obj.position_m);
      pd.origin_part_m = sp.orientation.toRotationMatrix().transpose() * (observer_body - sp.offset_m);
      pd.radius_m = shape_bounding_radius_m(pd.geom);
      if (shape_contains(pd.geom, pd.origin_part_m)) contains_observer = true;
      od.parts.push_back(pd);
      if (pd.geom.kind != ShapeKind::none) od.prim_part.push_back(static_cast<unsigned>(i));
    }
    data.push_back(std::move(od));
    ObjectData& stored = data.back();
    if (contains_observer || stored.prim_part.empty()) continue;  // invisible to this observer
    stored.attached = true;
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    check_embree(device, "rtcNewGeometry");
    rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(stored.prim_part.size()));
    rtcSetGeometryUserData(geom, &stored);
    rtcSetGeometryBoundsFunction(geom, bounds_callback, nullptr);
    rtcSetGeometryIntersectFunction(geom, intersect_callback);
    rtcSetGeometryOccludedFunction(geom, occluded_callback);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    check_embree(device, "user geometry");
  }
  rtcCommitScene(scene);
  check_embree(device, "rtcCommitScene");
}

namespace {
// Casts one ray from the observer; the double-precision nearest hit is left
// in rc (object -1: nothing).
void cast_one(RTCScene scene, RayContext& rc, RTCRayHit& rh, const Vec3& d, std::size_t i, const RayQuery& query) {
  rtcInitIntersectContext(&rc.ctx);
  rc.ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rc.query = query;
  rc.dir = d;
  rc.best_t = std::numeric_limits<double>::infinity();
  rc.object = rc.part = -1;
  rc.facet = -1;
  rh.ray.org_x = rh.ray.org_y = rh.ray.org_z = 0.0f;
  rh.ray.dir_x = static_cast<float>(d.x());
  rh.ray.dir_y = static_cast<float>(d.y());
  rh.ray.dir_z = static_cast<float>(d.z());
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.time = 0.0f;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.id = static_cast<unsigned>(i);
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &rc.ctx, &rh);
}

// Runs body(i, rc, rh) for i in [0, count) on `threads` workers, in blocks of
// consecutive (coherent) rays.
template <class Body>
void for_each_ray(std::size_t count, unsigned threads, const Body& body) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  constexpr std::size_t kBlock = 1024;
  const std::size_t n_blocks = (count + kBlock - 1) / kBlock;
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(1, n_blocks)));
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    RayContext rc;
    RTCRayHit rh;
    for (;;) {
      const std::size_t b = next.fetch_add(1);
      if (b >= n_blocks) return;
      const std::size_t end = std::min(count, (b + 1) * kBlock);
      for (std::size_t i = b * kBlock; i < end; ++i) body(i, rc, rh);
    }
  };
  run_workers(threads, [&](unsigned) { worker(); });
}
}  // namespace

namespace {
// The full hit of a ray cast_one left in rc.
Hit full_hit(const std::vector<ObjectData>& objects, const RayContext& rc, const Vec3& d) {
  Hit h;
  if (rc.object < 0) {
    h.range_m = sky_range_m;
    return h;
  }
  const ObjectData& od = objects[static_cast<std::size_t>(rc.object)];
  const PlacedObject& obj = *od.object;
  const PartData& pd = od.parts[static_cast<std::size_t>(rc.part)];
  h.object_id = obj.object_id;
  h.part = rc.part;
  h.facet = rc.facet;
  h.range_m = rc.best_t;
  h.point_body_m = obj.body_to_frame.transpose() * (rc.best_t * d - obj.position_m);
  h.normal_frame = pd.part_to_frame * rc.normal_part;  // a rotated unit normal
  return h;
}
}  // namespace

Hit RayCaster::cast(const Vec3& direction, const RayQuery& query) const {
  if (!impl_->scene) throw Error(Status::not_allowed, "ray caster: cast before build");
  RayContext rc;
  RTCRayHit rh;
  cast_one(impl_->scene, rc, rh, direction, 0, query);
  return full_hit(impl_->objects, rc, direction);
}

void RayCaster::cast(const std::vector<Vec3>& directions, std::vector<Hit>& hits, unsigned threads,
                     const RayQuery& query) const {
  if (!impl_->scene) throw Error(Status::not_allowed, "ray caster: cast before build");
  hits.resize(directions.size());  // every element is overwritten below
  const auto& objects = impl_->objects;
  RTCScene scene = impl_->scene;
  for_each_ray(directions.size(), threads, [&](std::size_t i, RayContext& rc, RTCRayHit& rh) {
    cast_one(scene, rc, rh, directions[i], i, query);
    hits[i] = full_hit(objects, rc, directions[i]);
  });
}

namespace {

// A cone of directions: unit axis and half-angle.
struct Cone {
  Vec3 axis;
  double half_angle_rad;
};

// The cone of a pinhole tile: its rays lie in the convex cone of its four
// corner rays, hence in the circular cone about their mean that holds them.
Cone tile_cone(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 axis = (a + b + c + d).normalized();
  double min_cos = 1.0;
  for (const Vec3* v : {&a, &b, &c, &d}) min_cos = std::min(min_cos, axis.dot(*v));
  return Cone{axis, std::acos(std::clamp(min_cos, -1.0, 1.0))};
}

// A part's bounding sphere as seen from the observer.
struct PartBound {
  int object = 0;        // index into Impl::objects
  unsigned part = 0;     // index into its parts
  Vec3 direction;        // unit, to the sphere's centre
  double angular_radius_rad = 0;
  bool surrounds_observer = false;
};

// Whether any ray of the cone may meet the sphere (conservative: padded far
// beyond the rounding of the angles).
bool cone_meets(const Cone& cone, const PartBound& b) {
  if (b.surrounds_observer) return true;
  const double angle = std::acos(std::clamp(cone.axis.dot(b.direction), -1.0, 1.0));
  return angle <= cone.half_angle_rad + b.angular_radius_rad + 1e-9;
}

}  // namespace

namespace {
// A tile near one object: its parts directly, in double, as the intersect
// callback would (nearest strictly closer wins): the tile's directions
// first, then each analytic part for all of them (independent rays back to
// back, so that their long chains of divisions and roots overlap), each
// mesh part's triangles in packets of 16 (coherent primary rays: Embree
// traverses a packet together).
template <class Direction, class Emit>
void cast_tile_near_one_object(const ObjectData& od, const std::vector<const PartBound*>& tile_bounds,
                               std::int64_t c0, std::int64_t r0, std::int64_t c1, std::int64_t r1,
                               const Direction& direction, const Emit& emit) {
  constexpr int kMax = 64;  // an 8 x 8 tile
  const int width = static_cast<int>(c1 - c0), rows = static_cast<int>(r1 - r0), n = width * rows;
  Vec3 d[kMax], d_part[kMax], normal_part[kMax];
  double best[kMax];
  int best_part[kMax];
  std::int32_t best_facet[kMax];
  // (ray i is column c0 + i % width, row r0 + i / width: counted, not divided)
  for (int i = 0, r = 0; r < rows; ++r)
    for (int c = 0; c < width; ++c, ++i) {
      d[i] = direction(c0 + c, r0 + r);
      best[i] = std::numeric_limits<double>::infinity();
      best_part[i] = -1;
      best_facet[i] = -1;
    }
  // (The rays into the part's axes as cast() turns them, rounding included:
  // transposed in the product where no part is a mesh, through the
  // transposed matrix where one is.)
  const bool any_mesh = std::any_of(tile_bounds.begin(), tile_bounds.end(), [&](const PartBound* b) {
    return od.parts[b->part].geom.kind == ShapeKind::mesh;
  });
  for (const PartBound* b : tile_bounds) {
    const PartData& p = od.parts[b->part];
    const Mat3 to_part = p.part_to_frame.transpose();
    if (any_mesh)
      for (int i = 0; i < n; ++i) d_part[i] = to_part * d[i];
    else  // (Eigen's transposed product written out, the same sums in the same order: its
          // result, stored a component at a time, is not reloaded as a pair)
      for (int i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k)
          d_part[i][k] = (p.part_to_frame(0, k) * d[i].x() + p.part_to_frame(1, k) * d[i].y()) +
                         p.part_to_frame(2, k) * d[i].z();
    if (p.geom.kind == ShapeKind::sphere || p.geom.kind == ShapeKind::oblate) {  // (the Earth's tiles: 4 rays at once)
      bool hit[kMax];
      double t[kMax];
      Vec3 nn[kMax];
      intersect_spheroid_rays(p.geom, p.origin_part_m, d_part, n, best, hit, t, nn);
      for (int i = 0; i < n; ++i)
        if (hit[i]) {
          best[i] = t[i];
          best_part[i] = static_cast<int>(b->part);
          best_facet[i] = -1;
          normal_part[i] = nn[i];
        }
      continue;
    }
    if (p.geom.kind != ShapeKind::mesh) {
      for (int i = 0; i < n; ++i) {
        double t = 0;
        Vec3 nn;
        if (intersect_shape(p.geom, p.origin_part_m, d_part[i], 0.0, best[i], t, nn)) {
          best[i] = t;
          best_part[i] = static_cast<int>(b->part);
          best_facet[i] = -1;
          normal_part[i] = nn;
        }
      }
      continue;
    }
    for (int i0 = 0; i0 < n; i0 += 16) {
      bool active[16];
      double t_max[16];
      Vec3 nn[16];
      std::int32_t facet[16];
      const int count = std::min(16, n - i0);
      for (int k = 0; k < count; ++k) {
        active[k] = true;
        t_max[k] = best[i0 + k];
      }
      if (p.geom.mesh->intersect16(p.geom.mesh_group, p.origin_part_m, d_part + i0, active, count, 0.0, t_max, nn,
                                   facet) == 0)
        continue;
      for (int k = 0; k < count; ++k)
        if (t_max[k] < best[i0 + k]) {
          best[i0 + k] = t_max[k];
          best_part[i0 + k] = static_cast<int>(b->part);
          best_facet[i0 + k] = facet[k];
          normal_part[i0 + k] = nn[k];
        }
    }
  }
  int i = 0;
  for (std::int64_t r = r0; r < r1; ++r)
    for (std::int64_t c = c0; c < c1; ++c, ++i) {
      if (best_part[i] < 0)
        emit(c, r, -1, -1, -1, sky_range_m, d[i], Vec3::Zero());
      else
        emit(c, r, od.object->object_id, best_part[i], best_facet[i], best[i], d[i],
             od.parts[static_cast<std::size_t>(best_part[i])].part_to_frame * normal_part[i]);
    }
}
}  // namespace

void RayCaster::cast_grid(std::int64_t width, std::int64_t height,
                          const std::function<Vec3(std::int64_t, std::int64_t)>& direction,
                          const std::function<void(std::int64_t, std::int64_t, std::int32_t, std::int32_t, std::int32_t,
                                                   double, const Vec3&, const Vec3&)>& emit,
                          unsigned threads, const RayQuery& query) const {
  cast_grid_tiles(
      width, height, direction,
      [&](const GridTile& tile) {
        for (int i = 0; i < tile.count; ++i)
          emit(tile.column[i], tile.row[i], tile.object[i], tile.part[i], tile.facet[i], tile.range_m[i],
               tile.direction[i], tile.normal_frame[i]);
      },
      threads, query);
}

void RayCaster::cast_grid_tiles(std::int64_t width, std::int64_t height,
                                const std::function<Vec3(std::int64_t, std::int64_t)>& direction,
                                const std::function<void(const GridTile&)>& emit_tile, unsigned threads,
                                const RayQuery& query) const {
  cast_tiles(width, height, direction, emit_tile, threads, query);
}

void RayCaster::cast_grid_tiles(std::int64_t width, std::int64_t height, const TangentGrid& directions,
                                const std::function<void(const GridTile&)>& emit_tile, unsigned threads,
                                const RayQuery& query) const {
  const auto direction = [&directions](std::int64_t c, std::int64_t r) -> Vec3 {
    return directions.body_to_frame * SampleGrid::direction_of_tangents(directions.tan_x[c], directions.tan_y[r]);
  };
  cast_tiles(width, height, direction, emit_tile, threads, query);
}

template <class Direction>
void RayCaster::cast_tiles(std::int64_t width, std::int64_t height, const Direction& direction,
                           const std::function<void(const GridTile&)>& emit_tile, unsigned threads,
                           const RayQuery& query) const {
  if (!impl_->scene) throw Error(Status::not_allowed, "ray caster: cast before build");
  if (width <= 0 || height <= 0) return;
  const auto& objects = impl_->objects;
  RTCScene scene = impl_->scene;
  // Bounding spheres of the parts of the objects the query admits and the
  // caster holds (an object containing the observer is invisible to it), in
  // the order of the objects and of their parts.
  std::vector<PartBound> bounds;
  for (const ObjectData& od : objects) {
    if (!od.attached || !admits(query, od)) continue;
    for (unsigned k : od.prim_part) {
      const PartData& p = od.parts[k];
      const double radius = p.radius_m * (1.0 + 1e-9), distance = p.centre_frame_m.norm();
      PartBound b;
      b.object = od.index;
      b.part = k;
      b.surrounds_observer = !(distance > radius);
      if (!b.surrounds_observer) {
        b.direction = p.centre_frame_m / distance;
        b.angular_radius_rad = std::asin(radius / distance);
      }
      bounds.push_back(b);
    }
  }
  constexpr std::int64_t kTile = 8, kBlock = 8;  // tiles of 8 x 8 samples, blocks of 8 x 8 tiles
  static_assert(kTile * kTile <= GridTile::kMaxSamples, "a tile fits GridTile");
  const std::int64_t tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;
  const std::int64_t blocks_x = (tiles_x + kBlock - 1) / kBlock, blocks_y = (tiles_y + kBlock - 1) / kBlock;
  const auto cone_of = [&](std::int64_t c0, std::int64_t r0, std::int64_t c1, std::int64_t r1) {
    return tile_cone(direction(c0, r0), direction(c1 - 1, r0), direction(c0, r1 - 1), direction(c1 - 1, r1 - 1));
  };
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<std::int64_t> next{0};
  auto worker = [&] {
    RayContext rc;
    RTCRayHit rh;
    std::vector<const PartBound*> block_bounds, tile_bounds;
    GridTile tile;
    const auto emit = [&tile](std::int64_t c, std::int64_t r, std::int32_t object, std::int32_t part,
                              std::int32_t facet, double range_m, const Vec3& d, const Vec3& normal_frame) {
      const int i = tile.count++;
      tile.column[i] = c;
      tile.row[i] = r;
      tile.object[i] = object;
      tile.part[i] = part;
      tile.facet[i] = facet;
      tile.range_m[i] = range_m;
      tile.direction[i] = d;
      tile.normal_frame[i] = normal_frame;
    };
    for (;;) {
      const std::int64_t block = next.fetch_add(1);
      if (block >= blocks_x * blocks_y) return;
      const std::int64_t bx = block % blocks_x, by = block / blocks_x;
      const std::int64_t bc0 = bx * kBlock * kTile, br0 = by * kBlock * kTile;
      const std::int64_t bc1 = std::min(width, bc0 + kBlock * kTile), br1 = std::min(height, br0 + kBlock * kTile);
      const Cone block_cone = cone_of(bc0, br0, bc1, br1);
      block_bounds.clear();
      for (const PartBound& b : bounds)
        if (cone_meets(block_cone, b)) block_bounds.push_back(&b);
      for (std::int64_t r0 = br0; r0 < br1; r0 += kTile)
        for (std::int64_t c0 = bc0; c0 < bc1; c0 += kTile) {
          const std::int64_t c1 = std::min(bc1, c0 + kTile), r1 = std::min(br1, r0 + kTile);
          tile.count = 0;
          tile_bounds.clear();
          if (!block_bounds.empty()) {
            const Cone cone = cone_of(c0, r0, c1, r1);
            for (const PartBound* b : block_bounds)
              if (cone_meets(cone, *b)) tile_bounds.push_back(b);
          }
          const bool one_object = !tile_bounds.empty() &&
                                  std::all_of(tile_bounds.begin(), tile_bounds.end(), [&](const PartBound* b) {
                                    return b->object == tile_bounds[0]->object;
                                  });
          if (one_object) {
            cast_tile_near_one_object(objects[static_cast<std::size_t>(tile_bounds[0]->object)], tile_bounds, c0, r0,
                                      c1, r1, direction, emit);
            emit_tile(tile);
            continue;
          }
          for (std::int64_t r = r0; r < r1; ++r)
            for (std::int64_t c = c0; c < c1; ++c) {
              if (tile_bounds.empty()) {  // no object near: the sky
                emit(c, r, -1, -1, -1, sky_range_m, Vec3::Zero(), Vec3::Zero());
                continue;
              }
              const Vec3 d = direction(c, r);
              cast_one(scene, rc, rh, d, 0, query);
              if (rc.object < 0) {
                emit(c, r, -1, -1, -1, sky_range_m, d, Vec3::Zero());
              } else {
                const ObjectData& od = objects[static_cast<std::size_t>(rc.object)];
                emit(c, r, od.object->object_id, rc.part, rc.facet, rc.best_t, d,
                     od.parts[static_cast<std::size_t>(rc.part)].part_to_frame * rc.normal_part);
              }
            }
          emit_tile(tile);
        }
    }
  };
  run_workers(static_cast<unsigned>(std::min<std::int64_t>(threads, blocks_x * blocks_y)), [&](unsigned) { worker(); });
}

bool RayCaster::occluded(const Vec3& d, double range_m, const RayQuery& query) const {
  if (!impl_->scene) throw Error(Status::not_allowed, "ray caster: cast before build");
  RayContext rc;
  rtcInitIntersectContext(&rc.ctx);
  rc.query = query;
  rc.dir = d;
  rc.best_t = range_m;
  rc.object = -1;
  RTCRay ray;
  ray.org_x = ray.org_y = ray.org_z = 0.0f;
  ray.dir_x = static_cast<float>(d.x());
  ray.dir_y = static_cast<float>(d.y());
  ray.dir_z = static_cast<float>(d.z());
  ray.tnear = 0.0f;
  ray.tfar = std::nextafter(static_cast<float>(range_m), std::numeric_limits<float>::infinity());
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  rtcOccluded1(impl_->scene, &rc.ctx, &ray);
  return rc.object >= 0;
}

}  // namespace eoir::geometry
