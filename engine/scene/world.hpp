// The world: an immutable, typed snapshot of the modeled universe for one
// (sensor, time) (DESIGN section 1, steps 1-2). Observer kinematics; every
// object placed relative to the observer in double precision, culled and
// classified once (outside the view, imaged as an extended area source, or
// a distant area source smaller than a sample, spec 4.1.6.1); its shape
// parts, its tessellation (made on first use) and its surface model; the
// light sources; and one committed ray caster. Everything that looks at the
// universe at that instant -- the image, target metrics, per-frame truth,
// picks -- reads this world and builds no other. It copies what it needs, so
// it stays valid after the universe changes.
#pragma once
#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/fidelity.hpp"
#include "core/time.hpp"
#include "geometry/sample_grid.hpp"
#include "geometry/scene_geometry.hpp"
#include "radiometry/spectral_view.hpp"
#include "scene/surface_model.hpp"
#include "universe/universe.hpp"

namespace eoir::scene {

using Mat3 = Eigen::Matrix3d;

// How the sensor's scene generator images an object (spec 4.1.3, 4.1.6.1).
enum class Imaging : int {
  outside = 0,       // wholly outside the view frustum (field plus guard band): culled
  extended = 1,      // resolved: ray-cast on the sample grid
  point_source = 2,  // smaller than a sample: kept apart at its focal-plane position
};

// What the sensor defines for the scene generator: its sample grid and
// spectral view (the sensor model resolves them), and its fidelity knobs.
struct ViewDefinition {
  geometry::SampleGrid grid;
  radiometry::SpectralView spectral;
  Fidelity fidelity;
};

struct Observer {
  Vec3 position_m = Vec3::Zero();    // geocentric J2000
  Vec3 velocity_m_s = Vec3::Zero();  // J2000
  Mat3 body_to_j2000 = Mat3::Identity();
};

// A light source that can illuminate a surface (eq. 4). Empty until
// sunlight arrives.
struct LightSource {};

class World;

class WorldObject {
 public:
  std::int32_t id = 0;  // index in World::objects, the ray caster's object_id
  std::string name;
  universe::ObjectKind kind = universe::ObjectKind::satellite;
  bool central_body = false;  // a background, not a target (per-frame truth)
  double equatorial_radius_m = 0, polar_radius_m = 0;  // central bodies: for latitude/longitude
  geometry::PlacedObject placed;  // parts, position relative to the observer (J2000 axes), body frame
  double range_m = 0;             // observer to body origin
  double bounding_radius_m = 0;   // sphere about the body origin enclosing every part
  Imaging imaging = Imaging::outside;
  double patch_size_m = 0;        // target edge of the tessellation's patches
  std::unique_ptr<SurfaceModel> surface;

  // The patches dA (spec 4.1.5.2), made on first use (thread-safe).
  const geometry::Tessellation& tessellation() const;
  // Outward unit normal (body frame) of `part` at a surface point.
  Vec3 normal_at(std::int32_t part, const Vec3& point_body_m) const;
  // Unit vector from the object toward the observer, body frame.
  Vec3 toward_observer_body() const;
  // The effective radiance (eq. 48) a sample ending at point_body_m on `part`
  // sees, as the scene mode says (spec 4.2): a part's value for uniform
  // surfaces; the value at the centre of the point's patch in coarse mode
  // (computed once per patch); the point's own in smooth mode.
  double radiance_at(std::int32_t part, const Vec3& point_body_m) const;
  // The normal at which that radiance is evaluated (patch or point normal).
  Vec3 shading_normal(std::int32_t part, const Vec3& point_body_m) const;
  // The radiance of patch k at its centre (cached).
  double patch_radiance(std::int32_t patch) const;
  // Projected area A*_T facing the observer (eq. 58, m^2): exact for a single
  // sphere, oblate, box, plate or cylinder, else the sum over patches.
  double projected_area_m2() const;
  // Band-integrated irradiance at the observer of the object seen as a point
  // (spec 4.1.6.1, ERRATA eq. 11: the sum of L dOmega over the visible
  // patches): L A* / R^2 for a single uniform shape, the patch sum otherwise.
  double point_irradiance_W_cm2() const;

 private:
  friend class World;
  friend std::shared_ptr<const World> build_world(const universe::Universe&, const EngineTime&,
                                                  const universe::Object&, const ViewDefinition&);
  const World* world_ = nullptr;
  mutable std::once_flag tessellated_;
  mutable geometry::Tessellation tessellation_;
  mutable std::unique_ptr<std::atomic<double>[]> patch_cache_;  // NaN until computed
};

class World {
 public:
  World() = default;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  EngineTime time;
  std::string sensor_name;
  Observer observer;
  ViewDefinition view;
  Vec3 sun_position_m = Vec3::Zero();  // relative to the observer, J2000 axes
  std::vector<std::unique_ptr<WorldObject>> objects;  // indexed by id
  std::vector<LightSource> lights;
  geometry::RayCaster caster;  // every placed object; ray masks tell how each is imaged

  const geometry::SampleGrid& grid() const { return view.grid; }
  const radiometry::SpectralView& spectral() const { return view.spectral; }
  const Fidelity& fidelity() const { return view.fidelity; }
  // Direction of sample (c, r) of the full grid, J2000 axes.
  Vec3 sample_direction(std::int64_t c, std::int64_t r) const {
    return observer.body_to_j2000 * view.grid.direction_body(c, r);
  }
  // nullptr if the world holds no object of that name (culled by kind, shape
  // none, no state, or the sensor's parent).
  const WorldObject* find(const std::string& name) const;
};

// Builds the world of `sensor` at t. Throws eoir::Error (no_state for a
// sensor whose parent has no state).
std::shared_ptr<const World> build_world(const universe::Universe& universe, const EngineTime& t,
                                         const universe::Object& sensor, const ViewDefinition& view);

}  // namespace eoir::scene
