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
#include <mutex>
#include <string>
#include <thread>

#include "core/error.hpp"
#include "geometry/scene_geometry.hpp"
#include "geometry/shape_intersect.hpp"

namespace eoir::geometry {
namespace {

// One shared device (creation is slow); its errors are recorded here.
std::mutex g_error_mutex;
std::string g_error_message;

void on_embree_error(void*, RTCError code, const char* message) {
  std::lock_guard<std::mutex> lock(g_error_mutex);
  g_error_message = "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "");
}

RTCDevice shared_device() {
  static std::once_flag once;
  static RTCDevice device = nullptr;
  std::call_once(once, [] {
    device = rtcNewDevice(nullptr);
    if (device) rtcSetDeviceErrorFunction(device, on_embree_error, nullptr);
  });
  if (!device) throw Error(Status::internal, "Embree: rtcNewDevice failed (" + std::to_string(rtcGetDeviceError(nullptr)) + ")");
  return device;
}

void check_device(RTCDevice device, const char* what) {
  const RTCError code = rtcGetDeviceError(device);
  if (code == RTC_ERROR_NONE) return;
  std::lock_guard<std::mutex> lock(g_error_mutex);
  throw Error(Status::internal, std::string("ray caster: ") + what + ": " + g_error_message);
}

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
  if (!intersect_shape(p.geom, p.origin_part_m, d, 0.0, rc->best_t, t, n)) return;
  rc->best_t = t;
  rc->object = od->index;
  rc->part = static_cast<int>(part_index);
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
    impl_->device = shared_device();
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
  check_device(device, "rtcNewScene");
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
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    check_device(device, "rtcNewGeometry");
    rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(stored.prim_part.size()));
    rtcSetGeometryUserData(geom, &stored);
    rtcSetGeometryBoundsFunction(geom, bounds_callback, nullptr);
    rtcSetGeometryIntersectFunction(geom, intersect_callback);
    rtcSetGeometryOccludedFunction(geom, occluded_callback);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    check_device(device, "user geometry");
  }
  rtcCommitScene(scene);
  check_device(device, "rtcCommitScene");
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
  if (threads == 1) {
    worker();
    return;
  }
  std::vector<std::thread> pool;
  for (unsigned k = 0; k < threads; ++k) pool.emplace_back(worker);
  for (auto& th : pool) th.join();
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
  h.range_m = rc.best_t;
  h.point_body_m = obj.body_to_frame.transpose() * (rc.best_t * d - obj.position_m);
  h.normal_frame = (pd.part_to_frame * rc.normal_part).normalized();
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

void RayCaster::cast_objects(std::size_t count, const std::function<Vec3(std::size_t)>& direction,
                             const std::function<void(std::size_t, std::int32_t, std::int32_t, double)>& emit,
                             unsigned threads, const RayQuery& query) const {
  if (!impl_->scene) throw Error(Status::not_allowed, "ray caster: cast before build");
  const auto& objects = impl_->objects;
  RTCScene scene = impl_->scene;
  for_each_ray(count, threads, [&](std::size_t i, RayContext& rc, RTCRayHit& rh) {
    cast_one(scene, rc, rh, direction(i), i, query);
    if (rc.object < 0) {
      emit(i, -1, -1, sky_range_m);
      return;
    }
    emit(i, objects[static_cast<std::size_t>(rc.object)].object->object_id, rc.part, rc.best_t);
  });
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
