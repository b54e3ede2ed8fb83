#include "scene/placement.hpp"

#include <algorithm>

#include "core/frames.hpp"
#include "geometry/projected_area.hpp"
#include "geometry/shape_intersect.hpp"
#include "scene/surface_shader.hpp"
#include "universe/composite.hpp"
#include "universe/object_motion.hpp"

namespace eoir::scene {
namespace {
// Default patch edge (spec 4.2.3: Earth tessellations about 785 km on a side,
// other central bodies the same number of patches; other objects an eighth of
// the diameter of their largest part).
double patch_size_m(const universe::Object& o, const std::vector<geometry::ShapePart>& parts) {
  if (o.body.patch_size_m > 0) return o.body.patch_size_m;
  if (o.kind == universe::ObjectKind::central_body) return 785.0e3 * o.body.dimensions_m[0] / 6378137.0;
  double size = 0;
  for (const auto& part : parts) size = std::max(size, 2.0 * geometry::shape_bounding_radius_m(geometry::shape_geom(part)));
  return std::max(size, 1e-6) / 8.0;
}
}  // namespace

std::vector<geometry::ShapePart> shape_parts(const universe::Object& o) {
  if (o.body.shape != "composite") {
    geometry::ShapePart part;
    part.shape = o.body.shape;
    part.dimensions_m = o.body.dimensions_m;
    part.temperature_K = o.body.temperature_K;
    part.reflectance = o.body.reflectance;
    return {part};
  }
  std::vector<geometry::ShapePart> parts;
  for (const universe::CompositePart& c : universe::parse_composite(o.body.composite, o.name + ".composite")) {
    geometry::ShapePart part;
    part.shape = c.shape;
    part.dimensions_m = c.dimensions_m;
    part.offset_m = c.offset_m;
    part.orientation = c.orientation;
    part.temperature_K = c.temperature_K.value_or(o.body.temperature_K);
    part.reflectance = c.reflectance.value_or(o.body.reflectance);
    parts.push_back(part);
  }
  return parts;
}

std::optional<Placement> place_object(const universe::Universe& universe, const universe::Object& o,
                                      const EngineTime& t, const geometry::Vec3& observer_position_m,
                                      std::int32_t object_id) {
  using universe::ObjectKind;
  if (o.kind == ObjectKind::sensor || o.kind == ObjectKind::star_field || o.body.shape == "none") return std::nullopt;
  if (o.kind != ObjectKind::central_body && !o.state.valid) return std::nullopt;  // not yet placed by the host
  const universe::Kinematics k = universe::kinematics_at(universe, o, t);
  Placement pl;
  pl.placed.parts = shape_parts(o);
  if (pl.placed.parts.empty()) return std::nullopt;  // a composite without parts
  geometry::PlacedObject& po = pl.placed;
  po.object_id = object_id;
  po.position_m = k.position_m - observer_position_m;
  po.central_body = o.kind == ObjectKind::central_body;
  const bool earth = po.central_body && o.name == "Earth";
  // Central bodies: Earth's body frame is Earth-fixed; the others keep J2000
  // axes (no rotation models yet).
  if (earth) po.body_to_frame = frames::j2000_to_earth_fixed(t).transpose();
  else if (po.central_body) po.body_to_frame.setIdentity();
  else po.body_to_frame = k.attitude.toRotationMatrix();
  pl.surface = FrameObject{o.name, po.central_body, {}, 0.0, 0.0, ThermalField{}};
  if (o.body.thermal_model == "subsolar") {
    ThermalField& th = pl.surface.thermal;
    th.subsolar = true;
    th.subsolar_K = o.body.subsolar_temperature_K;
    th.night_K = o.body.night_temperature_K;
    const universe::Kinematics sun = universe::kinematics_at(universe, universe.get("Sun"), t);
    th.sun_body = (po.body_to_frame.transpose() * (sun.position_m - k.position_m)).normalized();
  }
  if (po.central_body) {
    pl.surface.equatorial_radius_m = o.body.dimensions_m[0];
    pl.surface.polar_radius_m = o.body.dimensions_m[1];
  }
  for (const auto& part : po.parts) pl.surface.parts.push_back(SurfacePoint{part.temperature_K, part.reflectance});
  pl.range_m = po.position_m.norm();
  for (const auto& part : po.parts)
    pl.bounding_radius_m = std::max(pl.bounding_radius_m, part.offset_m.norm() + geometry::shape_bounding_radius_m(
                                                                                      geometry::shape_geom(part)));
  return pl;
}

void tessellate_placement(const universe::Object& o, Placement& placement) {
  placement.placed.tessellation =
      geometry::tessellate(placement.placed.parts, patch_size_m(o, placement.placed.parts));
}

double projected_solid_angle_sr(const Placement& pl) {
  const geometry::PlacedObject& po = pl.placed;
  const geometry::Vec3 toward_observer_body = -(po.body_to_frame.transpose() * po.position_m).normalized();
  return geometry::projected_area_m2(po.parts, po.tessellation, toward_observer_body) / (pl.range_m * pl.range_m);
}

double point_irradiance_W_cm2(const Placement& pl, const SpectralView& view) {
  const geometry::PlacedObject& po = pl.placed;
  const SurfaceShader shader(pl.surface, po, view, false);
  if (po.parts.size() == 1 && !shader.varying()) return shader.part_radiance(0) * projected_solid_angle_sr(pl);
  // Varying surfaces and composites: the sum over visible patches of L dOmega.
  const geometry::Vec3 toward_observer_body = -(po.body_to_frame.transpose() * po.position_m).normalized();
  double irradiance = 0;
  for (std::size_t k = 0; k < po.tessellation.patches.size(); ++k) {
    const geometry::Patch& patch = po.tessellation.patches[k];
    irradiance += shader.patch_radiance(static_cast<std::int32_t>(k)) *
                  std::max(0.0, patch.normal_body.dot(toward_observer_body)) * patch.area_m2;
  }
  return irradiance / (pl.range_m * pl.range_m);
}

}  // namespace eoir::scene
