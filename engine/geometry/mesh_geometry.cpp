// Meshes for the ray caster: Embree orders the candidates in float (vertices
// relative to the model's centre, rays moved to just before the group's
// bounding sphere, so float sees small numbers at any range) and the hit's
// range is recomputed in double on its triangle's plane, as the analytic
// shapes are solved in double (DESIGN.md section 3). A closed piece is seen
// only from outside: a back face of it is passed over.
#include "geometry/mesh_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

#include "core/error.hpp"
#include "geometry/embree_device.hpp"

namespace eoir::geometry {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Group {
  RTCScene scene = nullptr;
  std::vector<std::int32_t> triangles;  // Embree primID -> model triangle
  Vec3 centre_m = Vec3::Zero();         // bounding sphere
  double radius_m = 0;
  double radius_about_origin_m = 0;
  double area_m2 = 0, volume_m3 = 0;
};

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

struct MeshGeometry::Impl {
  RTCDevice device = nullptr;
  std::shared_ptr<const universe::MeshModel> model;
  Vec3 centre_m = Vec3::Zero();  // float vertices are relative to it
  std::vector<Vec3> vertices_m;
  std::vector<float> vertices_float;  // (x, y, z) - centre, padded by one float for Embree
  std::vector<Vec3> centroid_m, normal;
  std::vector<double> area_m2;
  std::vector<Group> groups;
  RTCScene whole = nullptr;
  std::vector<std::int32_t> whole_triangles;
  double size_m = 0;

  ~Impl() {
    for (Group& g : groups)
      if (g.scene) rtcReleaseScene(g.scene);
    if (whole) rtcReleaseScene(whole);
  }

  RTCScene build_scene(const std::vector<std::int32_t>& triangles) {
    RTCScene scene = rtcNewScene(device);
    check_embree(device, "mesh scene");
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices_float.data(), 0,
                               3 * sizeof(float), vertices_m.size());
    auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), triangles.size()));
    check_embree(device, "mesh index buffer");
    for (std::size_t i = 0; i < triangles.size(); ++i)
      for (int k = 0; k < 3; ++k)
        index[3 * i + k] = static_cast<unsigned>(model->triangles[static_cast<std::size_t>(triangles[i])][k]);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
    check_embree(device, "mesh hierarchy");
    return scene;
  }

  // The nearest triangle of `scene` met by origin + t dir, t in (t_min,
  // t_max) in double; closed back faces passed over unless `back_faces`.
  // Returns the primID, or -1.
  std::int64_t cast(RTCScene scene, const std::vector<std::int32_t>& triangles, const Vec3& origin, const Vec3& dir,
                    double t_start, double t_min, double t_max, bool back_faces, double& t_m) const {
    const Vec3 o = origin + t_start * dir - centre_m;
    float tnear = 0.0f;
    for (int attempt = 0; attempt < 64; ++attempt) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      RTCRayHit rh;
      rh.ray.org_x = static_cast<float>(o.x());
      rh.ray.org_y = static_cast<float>(o.y());
      rh.ray.org_z = static_cast<float>(o.z());
      rh.ray.dir_x = static_cast<float>(dir.x());
      rh.ray.dir_y = static_cast<float>(dir.y());
      rh.ray.dir_z = static_cast<float>(dir.z());
      rh.ray.tnear = tnear;
      rh.ray.tfar = t_max == kInf ? std::numeric_limits<float>::infinity()
                                  : std::nextafter(static_cast<float>(t_max - t_start) * 1.0001f + 1e-6f,
                                                   std::numeric_limits<float>::infinity());
      rh.ray.time = 0.0f;
      rh.ray.mask = 0xFFFFFFFFu;
      rh.ray.id = 0;
      rh.ray.flags = 0;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &context, &rh);
      if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return -1;
      const std::int32_t tri = triangles[rh.hit.primID];
      const Vec3& n = normal[static_cast<std::size_t>(tri)];
      const double facing = n.dot(dir);
      const Vec3& v0 = vertices_m[static_cast<std::size_t>(model->triangles[static_cast<std::size_t>(tri)][0])];
      const double t = facing != 0.0 ? n.dot(v0 - origin) / facing : t_start + rh.ray.tfar;
      const bool skip = (!back_faces && model->triangle_closed[static_cast<std::size_t>(tri)] && facing >= 0.0) ||
                        !(t > t_min);
      if (!skip) {
        if (!(t < t_max)) return -1;
        t_m = t;
        return rh.hit.primID;
      }
      tnear = std::nextafter(rh.ray.tfar, std::numeric_limits<float>::infinity());
    }
    return -1;
  }
};

MeshGeometry::MeshGeometry() : impl_(std::make_unique<Impl>()) {}
MeshGeometry::~MeshGeometry() = default;

std::shared_ptr<const MeshGeometry> MeshGeometry::of(const std::shared_ptr<const universe::MeshModel>& model,
                                                     double scale) {
  // Built once per model and scale; kept while the model lives (an entry
  // whose model is gone is dropped at the next call).
  static std::mutex mutex;
  static std::map<std::pair<const universe::MeshModel*, double>,
                  std::pair<std::weak_ptr<const universe::MeshModel>, std::shared_ptr<const MeshGeometry>>>
      cache;
  std::lock_guard<std::mutex> lock(mutex);
  for (auto it = cache.begin(); it != cache.end();) it = it->second.first.expired() ? cache.erase(it) : std::next(it);
  const auto key = std::make_pair(model.get(), scale);
  auto found = cache.find(key);
  if (found != cache.end()) return found->second.second;

  std::shared_ptr<MeshGeometry> g(new MeshGeometry());
  Impl& m = *g->impl_;
  m.device = embree_device();
  m.model = model;
  const universe::MeshModel& mm = *model;
  Vec3 lo = Vec3::Constant(kInf), hi = Vec3::Constant(-kInf);
  for (const Vec3& v : mm.vertices) {
    m.vertices_m.push_back(scale * v);
    lo = lo.cwiseMin(m.vertices_m.back());
    hi = hi.cwiseMax(m.vertices_m.back());
  }
  m.centre_m = 0.5 * (lo + hi);
  m.size_m = (hi - lo).norm();
  m.vertices_float.reserve(3 * m.vertices_m.size() + 1);
  for (const Vec3& v : m.vertices_m)
    for (int k = 0; k < 3; ++k) m.vertices_float.push_back(static_cast<float>(v[k] - m.centre_m[k]));
  m.vertices_float.push_back(0.0f);  // Embree reads 16 bytes at the last vertex
  const std::size_t n = mm.triangles.size();
  m.centroid_m.resize(n);
  m.normal.resize(n);
  m.area_m2.resize(n);
  m.groups.resize(mm.group_materials.size());
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = mm.triangles[t];
    const Vec3 &a = m.vertices_m[static_cast<std::size_t>(tri[0])], &b = m.vertices_m[static_cast<std::size_t>(tri[1])],
               &c = m.vertices_m[static_cast<std::size_t>(tri[2])];
    const Vec3 cross = (b - a).cross(c - a);
    m.centroid_m[t] = (a + b + c) / 3.0;
    m.area_m2[t] = 0.5 * cross.norm();
    m.normal[t] = cross.normalized();
    Group& group = m.groups[static_cast<std::size_t>(mm.triangle_group[t])];
    group.triangles.push_back(static_cast<std::int32_t>(t));
    group.area_m2 += m.area_m2[t] * (mm.triangle_closed[t] ? 1.0 : 2.0);
    if (mm.triangle_closed[t]) group.volume_m3 += a.dot(b.cross(c)) / 6.0;
    m.whole_triangles.push_back(static_cast<std::int32_t>(t));
  }
  for (Group& group : m.groups) {
    Vec3 glo = Vec3::Constant(kInf), ghi = Vec3::Constant(-kInf);
    for (std::int32_t t : group.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3& v = m.vertices_m[static_cast<std::size_t>(mm.triangles[static_cast<std::size_t>(t)][k])];
        glo = glo.cwiseMin(v);
        ghi = ghi.cwiseMax(v);
        group.radius_about_origin_m = std::max(group.radius_about_origin_m, v.norm());
      }
    group.centre_m = 0.5 * (glo + ghi);
    for (std::int32_t t : group.triangles)
      for (int k = 0; k < 3; ++k)
        group.radius_m = std::max(
            group.radius_m,
            (m.vertices_m[static_cast<std::size_t>(mm.triangles[static_cast<std::size_t>(t)][k])] - group.centre_m).norm());
    group.scene = m.build_scene(group.triangles);
  }
  m.whole = m.groups.size() == 1 ? nullptr : m.build_scene(m.whole_triangles);
  cache.emplace(key, std::make_pair(std::weak_ptr<const universe::MeshModel>(model), g));
  return g;
}

std::int32_t MeshGeometry::groups() const { return static_cast<std::int32_t>(impl_->groups.size()); }

const std::vector<std::int32_t>& MeshGeometry::group_triangles(std::int32_t group) const {
  return impl_->groups[static_cast<std::size_t>(group)].triangles;
}

bool MeshGeometry::intersect(std::int32_t group, const Vec3& origin_m, const Vec3& dir, double t_min, double t_max,
                             double& t_m, Vec3& normal, std::int32_t& facet) const {
  const Impl& m = *impl_;
  const Group& g = m.groups[static_cast<std::size_t>(group)];
  // The group's bounding sphere: a miss there is a miss; a hit starts the
  // float ray just before it.
  const Vec3 to_centre = g.centre_m - origin_m;
  const double along = to_centre.dot(dir);
  const double r = g.radius_m * (1.0 + 1e-6) + 1e-9;
  const double perp2 = (to_centre - along * dir).squaredNorm();
  if (perp2 > r * r) return false;
  const double t_start = std::max(t_min, along - std::sqrt(r * r - perp2)) - 1e-6 * r;
  if (!(t_start < t_max) || along + r < t_min) return false;
  double t = 0;
  const std::int64_t prim = m.cast(g.scene, g.triangles, origin_m, dir, t_start, t_min, t_max, false, t);
  if (prim < 0) return false;
  const Vec3& n = m.normal[static_cast<std::size_t>(g.triangles[static_cast<std::size_t>(prim)])];
  normal = n.dot(dir) > 0 ? Vec3(-n) : n;  // (closed: outward already; open: toward the ray)
  t_m = t;
  facet = static_cast<std::int32_t>(prim);
  return true;
}

int MeshGeometry::intersect16(std::int32_t group, const Vec3& origin_m, const Vec3* dirs, const bool* active,
                              int count, double t_min, double* t_max, Vec3* normal, std::int32_t* facet) const {
  const Impl& m = *impl_;
  const Group& g = m.groups[static_cast<std::size_t>(group)];
  const Vec3 to_centre = g.centre_m - origin_m;
  const double r = g.radius_m * (1.0 + 1e-6) + 1e-9;
  alignas(64) RTCRayHit16 rh;
  alignas(64) int valid[16];
  double t_start[16];
  int n_valid = 0;
  for (int k = 0; k < 16; ++k) {
    valid[k] = 0;
    rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    rh.ray.org_x[k] = rh.ray.org_y[k] = rh.ray.org_z[k] = rh.ray.dir_x[k] = rh.ray.dir_y[k] = 0.0f;
    rh.ray.dir_z[k] = 1.0f;
    rh.ray.tnear[k] = 0.0f;
    rh.ray.tfar[k] = 0.0f;
    rh.ray.time[k] = 0.0f;
    rh.ray.mask[k] = 0xFFFFFFFFu;
    rh.ray.id[k] = static_cast<unsigned>(k);
    rh.ray.flags[k] = 0;
    if (k >= count || !active[k]) continue;
    const Vec3& d = dirs[k];
    const double along = to_centre.dot(d);
    const double perp2 = (to_centre - along * d).squaredNorm();
    if (perp2 > r * r) continue;
    t_start[k] = std::max(t_min, along - std::sqrt(r * r - perp2)) - 1e-6 * r;
    if (!(t_start[k] < t_max[k]) || along + r < t_min) continue;
    const Vec3 o = origin_m + t_start[k] * d - m.centre_m;
    rh.ray.org_x[k] = static_cast<float>(o.x());
    rh.ray.org_y[k] = static_cast<float>(o.y());
    rh.ray.org_z[k] = static_cast<float>(o.z());
    rh.ray.dir_x[k] = static_cast<float>(d.x());
    rh.ray.dir_y[k] = static_cast<float>(d.y());
    rh.ray.dir_z[k] = static_cast<float>(d.z());
    rh.ray.tfar[k] = t_max[k] == kInf ? std::numeric_limits<float>::infinity()
                                      : std::nextafter(static_cast<float>(t_max[k] - t_start[k]) * 1.0001f + 1e-6f,
                                                       std::numeric_limits<float>::infinity());
    valid[k] = -1;
    ++n_valid;
  }
  if (n_valid == 0) return 0;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcIntersect16(valid, g.scene, &context, &rh);
  int hits = 0;
  for (int k = 0; k < 16; ++k) {
    if (!valid[k] || rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) continue;
    const Vec3& d = dirs[k];
    const std::int32_t tri = g.triangles[rh.hit.primID[k]];
    const Vec3& n = m.normal[static_cast<std::size_t>(tri)];
    const double facing = n.dot(d);
    const Vec3& v0 = m.vertices_m[static_cast<std::size_t>(m.model->triangles[static_cast<std::size_t>(tri)][0])];
    const double t = facing != 0.0 ? n.dot(v0 - origin_m) / facing : t_start[k] + rh.ray.tfar[k];
    if ((m.model->triangle_closed[static_cast<std::size_t>(tri)] && facing >= 0.0) || !(t > t_min)) {
      // (a closed back face or a hit behind t_min, rare: the single ray passes over it)
      double t1 = 0;
      Vec3 n1;
      std::int32_t f1 = -1;
      if (intersect(group, origin_m, d, t_min, t_max[k], t1, n1, f1)) {
        t_max[k] = t1;
        normal[k] = n1;
        facet[k] = f1;
        ++hits;
      }
      continue;
    }
    if (!(t < t_max[k])) continue;
    t_max[k] = t;
    normal[k] = facing > 0 ? Vec3(-n) : n;
    facet[k] = static_cast<std::int32_t>(rh.hit.primID[k]);
    ++hits;
  }
  return hits;
}

bool MeshGeometry::contains(const Vec3& p_m) const {
  const Impl& m = *impl_;
  RTCScene scene = m.whole ? m.whole : m.groups[0].scene;
  const std::vector<std::int32_t>& triangles = m.whole ? m.whole_triangles : m.groups[0].triangles;
  // From inside a closed piece the first closed triangle along any ray is
  // seen from behind; sheets in between are passed over.
  const Vec3 dir = Vec3(0.5773, 0.5774, 0.5775).normalized();
  const double depth = 1e-9 * m.size_m;
  double t_min = 0.0;
  for (int k = 0; k < 64; ++k) {
    double t = 0;
    const std::int64_t prim = m.cast(scene, triangles, p_m, dir, 0.0, t_min, kInf, true, t);
    if (prim < 0) return false;
    const std::int32_t tri = triangles[static_cast<std::size_t>(prim)];
    if (m.model->triangle_closed[static_cast<std::size_t>(tri)])
      return m.normal[static_cast<std::size_t>(tri)].dot(dir) > 0 && t > depth;
    t_min = t;
  }
  return false;
}

std::int32_t MeshGeometry::nearest_triangle(std::int32_t group, const Vec3& p_m) const {
  const Impl& m = *impl_;
  const Group& g = m.groups[static_cast<std::size_t>(group)];
  struct Query {
    const Impl* m;
    const Group* g;
    Vec3 p;
    double best2 = kInf;
    std::int32_t best = -1;
  } q{&m, &g, p_m};
  RTCPointQuery query;
  const Vec3 local = p_m - m.centre_m;
  query.x = static_cast<float>(local.x());
  query.y = static_cast<float>(local.y());
  query.z = static_cast<float>(local.z());
  query.time = 0.0f;
  query.radius = std::numeric_limits<float>::infinity();
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(
      g.scene, &query, &context,
      [](RTCPointQueryFunctionArguments* args) -> bool {
        auto* state = static_cast<Query*>(args->userPtr);
        const std::int32_t tri = state->g->triangles[args->primID];
        const auto& t = state->m->model->triangles[static_cast<std::size_t>(tri)];
        const auto& v = state->m->vertices_m;
        const Vec3 c = closest_on_triangle(state->p, v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])],
                                           v[static_cast<std::size_t>(t[2])]);
        const double d2 = (c - state->p).squaredNorm();
        if (d2 < state->best2) {
          state->best2 = d2;
          state->best = tri;
          // (padded: the hierarchy's boxes are float)
          args->query->radius = static_cast<float>(std::sqrt(d2) * (1.0 + 1e-5) + 1e-6 * state->m->size_m);
          return true;
        }
        return false;
      },
      &q);
  return q.best >= 0 ? q.best : g.triangles.front();
}

double MeshGeometry::bounding_radius_m(std::int32_t group) const {
  return impl_->groups[static_cast<std::size_t>(group)].radius_about_origin_m;
}
double MeshGeometry::surface_area_m2(std::int32_t group) const {
  return impl_->groups[static_cast<std::size_t>(group)].area_m2;
}
double MeshGeometry::volume_m3(std::int32_t group) const {
  return impl_->groups[static_cast<std::size_t>(group)].volume_m3;
}
const Eigen::Vector3d& MeshGeometry::centroid_m(std::int32_t t) const { return impl_->centroid_m[static_cast<std::size_t>(t)]; }
const Eigen::Vector3d& MeshGeometry::normal(std::int32_t t) const { return impl_->normal[static_cast<std::size_t>(t)]; }
double MeshGeometry::area_m2(std::int32_t t) const { return impl_->area_m2[static_cast<std::size_t>(t)]; }
bool MeshGeometry::one_sided(std::int32_t t) const { return impl_->model->triangle_closed[static_cast<std::size_t>(t)] != 0; }

}  // namespace eoir::geometry
