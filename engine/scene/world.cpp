#include "scene/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "core/frames.hpp"
#include "geometry/projected_area.hpp"
#include "universe/object_motion.hpp"

namespace eoir::scene {
namespace {
using universe::ObjectKind;

// True if a sphere (centre in sensor body axes, radius) lies wholly outside
// the pyramid of the sample grid (field of view plus guard band).
bool outside_view(const Vec3& centre_body, double radius, const geometry::SampleGrid& grid) {
  if (centre_body.norm() <= radius) return false;  // around the sensor: let the ray caster decide
  const double tx = std::fabs(grid.tan_x(0)), ty = std::fabs(grid.tan_y(0));
  // Outward unit normals of the four side planes of the pyramid.
  const Vec3 planes[4] = {Vec3(1, 0, -tx).normalized(), Vec3(-1, 0, -tx).normalized(), Vec3(0, 1, -ty).normalized(),
                          Vec3(0, -1, -ty).normalized()};
  for (const Vec3& n : planes)
    if (n.dot(centre_body) > radius) return true;
  return false;
}

// Default patch edge (spec 4.1.5.2, 4.2.3) from the sensor's fidelity.
double patch_size_m(const universe::Object& o, const std::vector<geometry::ShapePart>& parts, const Fidelity& f) {
  if (o.body.patch_size_m > 0) return o.body.patch_size_m;
  if (o.kind == ObjectKind::central_body)
    return f.central_body_patch_size_m * o.body.dimensions_m[0] / 6378137.0;  // scaled from the Earth's radius
  double size = 0;
  for (const auto& part : parts) size = std::max(size, 2.0 * geometry::shape_bounding_radius_m(part.geom));
  return std::max(size, 1e-6) / f.object_patch_divisions;
}

// Places one object relative to the observer; nullptr for objects that image
// nothing (sensors, the star field, shape none, an empty composite) or that
// the host has not placed yet.
std::unique_ptr<WorldObject> place(const universe::Universe& universe, const universe::Object& o, const EngineTime& t,
                                   const World& world, const Vec3& sun_geocentric_m) {
  if (o.kind == ObjectKind::sensor || o.kind == ObjectKind::star_field) return nullptr;
  if (o.kind != ObjectKind::central_body && !o.state.valid) return nullptr;
  const std::vector<universe::ShapePart> shape = universe::shape_parts(o.body);
  if (shape.empty()) return nullptr;
  const universe::Kinematics k = universe::kinematics_at(universe, o, t);
  auto w = std::make_unique<WorldObject>();
  w->name = o.name;
  w->kind = o.kind;
  w->central_body = o.kind == ObjectKind::central_body;
  geometry::PlacedObject& po = w->placed;
  std::vector<PartSurface> surfaces;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const std::string field = o.body.shape == universe::ShapeKind::composite
                                  ? o.name + ".composite[" + std::to_string(i) + "]"
                                  : o.name + ".shape";
    po.parts.push_back(geometry::make_part(shape[i], field));
    surfaces.push_back(PartSurface{shape[i].temperature_K.value_or(o.body.temperature_K),
                                   shape[i].reflectance.value_or(o.body.reflectance)});
  }
  po.position_m = k.position_m - world.observer.position_m;
  if (w->central_body) {
    const universe::CentralBodyInfo& info = universe::central_body_info(o.central_body);
    po.body_to_frame = info.axes == universe::BodyAxes::earth_fixed ? Mat3(frames::j2000_to_earth_fixed(t).transpose())
                                                                     : Mat3(Mat3::Identity());
    w->equatorial_radius_m = o.body.dimensions_m[0];
    w->polar_radius_m = o.body.dimensions_m[1];
  } else {
    po.body_to_frame = k.attitude.toRotationMatrix();
  }
  ThermalField thermal;
  if (o.body.thermal_model == universe::ThermalModel::subsolar) {
    thermal.subsolar = true;
    thermal.subsolar_K = o.body.subsolar_temperature_K;
    thermal.night_K = o.body.night_temperature_K;
    thermal.sun_body = (po.body_to_frame.transpose() * (sun_geocentric_m - k.position_m)).normalized();
  }
  const Fidelity& f = world.view.fidelity;
  w->surface = std::make_unique<SurfaceModel>(std::move(surfaces), thermal, world.view.spectral,
                                              f.scene_mode == SceneMode::smooth ? f.temperature_table_size : 0);
  w->range_m = po.position_m.norm();
  for (const auto& part : po.parts)
    w->bounding_radius_m =
        std::max(w->bounding_radius_m, part.offset_m.norm() + geometry::shape_bounding_radius_m(part.geom));
  w->patch_size_m = patch_size_m(o, po.parts, f);
  return w;
}
}  // namespace

const geometry::Tessellation& WorldObject::tessellation() const {
  std::call_once(tessellated_, [this] {
    tessellation_ = geometry::tessellate(placed.parts, patch_size_m);
    const std::size_t n = tessellation_.patches.size();
    patch_cache_ = std::make_unique<std::atomic<double>[]>(n);
    for (std::size_t i = 0; i < n; ++i)
      patch_cache_[i].store(std::numeric_limits<double>::quiet_NaN(), std::memory_order_relaxed);
  });
  return tessellation_;
}

Vec3 WorldObject::normal_at(std::int32_t part, const Vec3& point_body_m) const {
  const geometry::ShapePart& sp = placed.parts[static_cast<std::size_t>(part < 0 ? 0 : part)];
  const Vec3 local = sp.orientation.conjugate() * (point_body_m - sp.offset_m);
  return (sp.orientation * geometry::shape_normal(sp.geom, local)).normalized();
}

Vec3 WorldObject::toward_observer_body() const {
  return -(placed.body_to_frame.transpose() * placed.position_m).normalized();
}

double WorldObject::patch_radiance(std::int32_t patch) const {
  const geometry::Patch& p = tessellation().patches[static_cast<std::size_t>(patch)];
  if (!surface->varying()) return surface->part_radiance(p.part);
  std::atomic<double>& cached = patch_cache_[static_cast<std::size_t>(patch)];
  double L = cached.load(std::memory_order_relaxed);
  if (std::isnan(L)) {  // two threads may both compute it: the same value
    L = surface->effective_radiance(p.part, p.normal_body);
    cached.store(L, std::memory_order_relaxed);
  }
  return L;
}

Vec3 WorldObject::shading_normal(std::int32_t part, const Vec3& point_body_m) const {
  if (world_->view.fidelity.scene_mode == SceneMode::smooth) return normal_at(part, point_body_m);
  const std::int32_t k = geometry::patch_at(tessellation(), placed.parts, part, point_body_m);
  return tessellation().patches[static_cast<std::size_t>(k)].normal_body;
}

double WorldObject::radiance_at(std::int32_t part, const Vec3& point_body_m) const {
  if (!surface->varying()) return surface->part_radiance(part);
  if (world_->view.fidelity.scene_mode == SceneMode::smooth)
    return surface->effective_radiance_interpolated(part, normal_at(part, point_body_m));
  return patch_radiance(geometry::patch_at(tessellation(), placed.parts, part, point_body_m));
}

double WorldObject::projected_area_m2() const {
  const Vec3 v = toward_observer_body();
  if (placed.parts.size() == 1) {
    const double a = geometry::analytic_projected_area_m2(placed.parts[0], v);
    if (a >= 0) return a;
  }
  return geometry::projected_area_m2(placed.parts, tessellation(), v);
}

double WorldObject::point_irradiance_W_cm2() const {
  const double r2 = range_m * range_m;
  if (placed.parts.size() == 1 && !surface->varying()) return surface->part_radiance(0) * (projected_area_m2() / r2);
  // Varying surfaces and composites: the sum over visible patches of L dOmega.
  const Vec3 v = toward_observer_body();
  const geometry::Tessellation& t = tessellation();
  double irradiance = 0;
  for (std::size_t k = 0; k < t.patches.size(); ++k) {
    const geometry::Patch& patch = t.patches[k];
    irradiance += patch_radiance(static_cast<std::int32_t>(k)) * std::max(0.0, patch.normal_body.dot(v)) * patch.area_m2;
  }
  return irradiance / r2;
}

const WorldObject* World::find(const std::string& name) const {
  for (const auto& o : objects)
    if (o->name == name) return o.get();
  return nullptr;
}

std::shared_ptr<const World> build_world(const universe::Universe& universe, const EngineTime& t,
                                         const universe::Object& sensor, const ViewDefinition& view) {
  auto world = std::make_shared<World>();
  world->time = t;
  world->sensor_name = sensor.name;
  world->view = view;
  const universe::Kinematics k = universe::kinematics_at(universe, sensor, t);
  world->observer = Observer{k.position_m, k.velocity_m_s, k.attitude.toRotationMatrix()};
  frames::Vec3 sun_r, sun_v;
  universe::central_body_state_j2000(universe::central_body_info(universe::CentralBody::sun), t, sun_r, sun_v);
  world->sun_position_m = sun_r - world->observer.position_m;
  const Mat3 j2000_to_body = world->observer.body_to_j2000.transpose();
  const geometry::SampleGrid& grid = world->view.grid;
  const double sample_angle_rad = grid.sample_angle_rad();
  std::vector<const geometry::PlacedObject*> cast_against;
  for (const universe::Object& o : universe.objects()) {
    if (o.name == sensor.parent) continue;  // a sensor never images its parent (4.1.5.1)
    std::unique_ptr<WorldObject> w = place(universe, o, t, *world, sun_r);
    if (!w) continue;
    w->id = static_cast<std::int32_t>(world->objects.size());
    w->world_ = world.get();
    w->placed.object_id = w->id;
    // Classified once (DESIGN section 1, step 2).
    const double range = w->range_m, radius = w->bounding_radius_m;
    if (outside_view(j2000_to_body * w->placed.position_m, radius, grid))
      w->imaging = Imaging::outside;
    else if (range > radius && 2.0 * std::asin(std::min(1.0, radius / range)) < sample_angle_rad)
      w->imaging = Imaging::point_source;  // a distant area source smaller than a sample (4.1.6.1)
    else
      w->imaging = Imaging::extended;
    w->placed.ray_mask = w->imaging == Imaging::extended ? geometry::ray_mask_extended : geometry::ray_mask_other;
    world->objects.push_back(std::move(w));
  }
  for (const auto& w : world->objects) cast_against.push_back(&w->placed);
  world->caster.build(cast_against);
  return world;
}

}  // namespace eoir::scene
