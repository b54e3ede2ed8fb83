// The geometric scene the scene generator ray-casts (spec 4.1.3, 4.1.5):
// objects made of analytic shape parts, placed relative to the observer in
// double precision (DESIGN.md section 3), each surface divided into patches dA.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace eoir::geometry {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// One simple shape of spec 4.1.5.1 inside an object, in the object's body
// frame. Shapes and their dimensions (metres) are those of
// universe/shapes.hpp: sphere [r], oblate [a, c] (ellipsoid, c along body z),
// box [x, y, z], plate [x, y] (zero thickness, normal +z, seen from both sides),
// cylinder [r, length] (axis z, centred), cone [r_base, length] (base at
// z = -length/2, apex at +length/2), coupler [r_base, r_top, length] (frustum),
// none (never hit).
struct ShapePart {
  std::string shape = "sphere";
  std::vector<double> dimensions_m{1.0};
  Vec3 offset_m = Vec3::Zero();                              // part origin in body frame
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // part -> body
  std::int32_t material = 0;     // index into the caller's material list
  double temperature_K = 0.0;
  double reflectance = 0.0;      // gray-body SRF
};

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
  std::vector<std::vector<std::int32_t>> grid;  // free for the implementation
  double target_patch_size_m = 0.0;
};

// Divides every part into patches whose edge is about target_patch_size_m
// (sphere/ellipsoid: latitude bands with longitude cells of equal area; flat
// faces: rectangular grids; cylinders/cones/couplers: side grid + caps).
Tessellation tessellate(const std::vector<ShapePart>& parts, double target_patch_size_m);
// The patch containing `point_body_m` on part `part` (the point is on or very
// near that part's surface).
std::int32_t patch_at(const Tessellation& t, const std::vector<ShapePart>& parts, std::int32_t part,
                      const Vec3& point_body_m);

// One object placed in the observer-relative frame (axes of J2000, origin at
// the observer).
struct PlacedObject {
  std::int32_t object_id = 0;          // caller's identifier, returned in hits
  std::vector<ShapePart> parts;
  Tessellation tessellation;
  Vec3 position_m = Vec3::Zero();      // body origin relative to the observer (double)
  Mat3 body_to_frame = Mat3::Identity();
  bool central_body = false;           // informational
};

// The nearest surface a ray meets, or the sky (object_id == -1).
struct Hit {
  std::int32_t object_id = -1;
  std::int32_t part = -1;
  std::int32_t patch = -1;
  double range_m = 0.0;               // along the ray; sky: see sky_range_m
  Vec3 point_body_m = Vec3::Zero();   // hit point in the object's body frame
  Vec3 normal_frame = Vec3::Zero();   // outward surface normal, observer frame
};

// 1000 times Neptune's orbital radius (30.07 AU), spec 4.1.3.
constexpr double sky_range_m = 1000.0 * 30.07 * 149597870700.0;

// Ray casting with Embree 3: every part is an Embree user geometry whose
// intersection is computed analytically in double precision relative to the
// observer (rays start at the observer, the origin). Build once per frame.
class RayCaster {
 public:
  RayCaster();
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // Objects must outlive the caster (it keeps pointers).
  void build(const std::vector<PlacedObject>& objects);
  // directions: unit vectors in the observer frame (double). Fills hits
  // (resized). threads: 0 = all cores. Rays are cast in coherent blocks.
  void cast(const std::vector<Vec3>& directions, std::vector<Hit>& hits, unsigned threads = 0) const;

  // The lean form for whole frames: ray i's direction comes from
  // direction(i) and its nearest surface goes to emit(i, object_id, part,
  // range_m) (object_id -1: the sky). Neither directions nor full hits are
  // stored, and no point, normal or patch is computed (cast one ray with the
  // form above where those are needed). Both callbacks are called from the
  // worker threads, each index once.
  void cast_objects(std::size_t count, const std::function<Vec3(std::size_t)>& direction,
                    const std::function<void(std::size_t, std::int32_t, std::int32_t, double)>& emit,
                    unsigned threads = 0) const;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace eoir::geometry

namespace eoir::geometry {
// Helper appended by the geometry helper: like patch_at, but picks the face of
// a two-sided plate from the seen side's outward normal (body frame); for every
// other shape identical to patch_at. A plate's patches are its +z face grid
// followed by its -z face grid (both faces are tessellated, spec 4.1.5.2).
std::int32_t patch_at_facing(const Tessellation& t, const std::vector<ShapePart>& parts, std::int32_t part,
                             const Vec3& point_body_m, const Vec3& normal_body);
}  // namespace eoir::geometry
