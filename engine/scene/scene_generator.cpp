#include "scene/scene_generator.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "geometry/projected_area.hpp"
#include "universe/central_bodies.hpp"
#include "universe/object_motion.hpp"

namespace eoir::scene {
namespace {
using geometry::Vec3;

// Default patch edge (spec 4.2.3: Earth tessellations about 785 km on a side,
// other central bodies the same number of patches; other objects an eighth of
// their largest dimension).
double patch_size_m(const universe::Object& o) {
  if (o.body.patch_size_m > 0) return o.body.patch_size_m;
  if (o.kind == universe::ObjectKind::central_body) return 785.0e3 * o.body.dimensions_m[0] / 6378137.0;
  double size = 0;
  for (double d : o.body.dimensions_m) size = std::max(size, d);
  return std::max(size, 1e-6) / 8.0;
}

// Radius of a sphere about the body origin enclosing every part.
double bounding_radius_m(const std::vector<geometry::ShapePart>& parts) {
  double r = 0;
  for (const auto& p : parts) {
    const auto& d = p.dimensions_m;
    double extent = 0;
    if (p.shape == "sphere") extent = d[0];
    else if (p.shape == "oblate") extent = std::max(d[0], d[1]);
    else if (p.shape == "box") extent = 0.5 * std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    else if (p.shape == "plate") extent = 0.5 * std::sqrt(d[0] * d[0] + d[1] * d[1]);
    else if (p.shape == "cylinder" || p.shape == "cone") extent = std::hypot(d[0], 0.5 * d[1]);
    else if (p.shape == "coupler") extent = std::hypot(std::max(d[0], d[1]), 0.5 * d[2]);
    r = std::max(r, p.offset_m.norm() + extent);
  }
  return r;
}

// True if a sphere (centre in sensor body axes, radius) lies wholly outside
// the pyramid of the sample grid (field of view plus guard band).
bool outside_view(const Vec3& centre_body, double radius, const SampleGrid& grid) {
  if (centre_body.norm() <= radius) return false;  // around the sensor: let the ray caster decide
  const double tx = std::fabs(grid.tan_x(0)), ty = std::fabs(grid.tan_y(0));
  // Outward unit normals of the four side planes of the pyramid.
  const Vec3 planes[4] = {Vec3(1, 0, -tx).normalized(), Vec3(-1, 0, -tx).normalized(), Vec3(0, 1, -ty).normalized(),
                          Vec3(0, -1, -ty).normalized()};
  for (const Vec3& n : planes)
    if (n.dot(centre_body) > radius) return true;
  return false;
}

bool images_nothing(const universe::Object& o) {
  return o.kind == universe::ObjectKind::sensor || o.kind == universe::ObjectKind::star_field ||
         o.body.shape == "none";
}
}  // namespace

std::vector<geometry::ShapePart> shape_parts(const universe::Object& o) {
  geometry::ShapePart part;
  part.shape = o.body.shape;
  part.dimensions_m = o.body.dimensions_m;
  part.temperature_K = o.body.temperature_K;
  part.reflectance = o.body.reflectance;
  return {part};
}

void generate_scene(const universe::Universe& universe, const EngineTime& t, const universe::Object& sensor,
                    const sensor::StaticMetrics& metrics, unsigned threads, Frame& frame) {
  const sensor::SensorParameters& p = sensor.sensor;
  frame.time = t;
  frame.grid = make_sample_grid(p, metrics);
  frame.spectral = SpectralView::make(p.band_low_um, p.band_high_um, p.spectral_intervals,
                                      p.band_integration == "exact" ? BandIntegration::exact : BandIntegration::grid);
  const universe::Kinematics observer = universe::kinematics_at(universe, sensor, t);
  frame.body_to_j2000 = observer.attitude.toRotationMatrix();
  frame.boresight_j2000 = frame.body_to_j2000.col(2);
  frame.up_j2000 = frame.body_to_j2000.col(1);
  const Eigen::Matrix3d j2000_to_body = frame.body_to_j2000.transpose();
  const SampleGrid& grid = frame.grid;
  const double sample_angle_rad = std::min(grid.pitch_x_cm, grid.pitch_y_cm) / SampleGrid::per_pixel /
                                  grid.focal_length_cm;

  // 1-2. Snapshot relative to the sensor; cull and classify (DESIGN.md 1).
  frame.objects.clear();
  frame.point_sources.clear();
  std::vector<geometry::PlacedObject> placed;
  for (const universe::Object& o : universe.objects()) {
    if (images_nothing(o) || o.name == sensor.parent) continue;  // a sensor never images its parent (4.1.5.1)
    if (o.kind != universe::ObjectKind::central_body && !o.state.valid) continue;  // not yet placed by the host
    const universe::Kinematics k = universe::kinematics_at(universe, o, t);
    geometry::PlacedObject po;
    po.object_id = static_cast<std::int32_t>(frame.objects.size());
    po.parts = shape_parts(o);
    po.position_m = k.position_m - observer.position_m;
    po.central_body = o.kind == universe::ObjectKind::central_body;
    const bool earth = po.central_body && o.name == "Earth";
    // Central bodies: Earth's body frame is Earth-fixed; the others keep
    // J2000 axes (no rotation models yet).
    po.body_to_frame = earth ? frames::j2000_to_earth_fixed(t).transpose() : k.attitude.toRotationMatrix();
    if (po.central_body && !earth) po.body_to_frame.setIdentity();
    FrameObject fo{o.name, po.central_body, earth, SurfacePoint{o.body.temperature_K, o.body.reflectance}};
    frame.objects.push_back(fo);

    const double range = po.position_m.norm();
    const double radius = bounding_radius_m(po.parts);
    if (outside_view(j2000_to_body * po.position_m, radius, grid)) {
      frame.objects.pop_back();  // culled: costs nothing more (DESIGN.md 4)
      continue;
    }
    po.tessellation = geometry::tessellate(po.parts, patch_size_m(o));
    if (range > radius && 2.0 * std::asin(std::min(1.0, radius / range)) < sample_angle_rad) {
      // A distant area source (spec 4.1.6.1): E = sum over the visible
      // patches of L dOmega (ERRATA eq. 11). With one radiance over the whole
      // surface (self-emission of a uniform object) that sum is L A* / R^2
      // with the projected area A* of eq. 58, taken exactly for analytic
      // shapes rather than from the patches.
      double c = 0, r = 0;
      if (!grid.sample_of(j2000_to_body * po.position_m, c, r)) continue;
      const double g = static_cast<double>(grid.guard_samples()), tol = 1e-9;
      const bool inside = c >= g - 0.5 - tol && c <= g + 4.0 * grid.pixels_x - 0.5 + tol &&
                          r >= g - 0.5 - tol && r <= g + 4.0 * grid.pixels_y - 0.5 + tol;
      if (!inside) continue;  // ideal field of view (spec 5.2, 7.2.1)
      const double radiance = effective_radiance(fo.surface, frame.spectral);
      const Vec3 toward_observer_body = -(po.body_to_frame.transpose() * po.position_m).normalized();
      const double area_m2 = geometry::projected_area_m2(po.parts, po.tessellation, toward_observer_body);
      const double irradiance = radiance * area_m2 / (range * range);
      frame.point_sources.push_back(PointSource{po.object_id, c, r, irradiance, range});
      continue;
    }
    placed.push_back(std::move(po));
  }

  // 3. Ray-cast the sample grid (spec 4.1.3) in the observer frame.
  const std::int64_t w = grid.width(), h = grid.height();
  std::vector<Vec3> directions(static_cast<std::size_t>(w * h));
  for (std::int64_t r = 0; r < h; ++r)
    for (std::int64_t c = 0; c < w; ++c)
      directions[static_cast<std::size_t>(r * w + c)] = frame.body_to_j2000 * grid.direction_body(c, r);
  geometry::RayCaster caster;
  caster.build(placed);
  caster.cast(directions, frame.hits, threads);

  // 4-5. Shade only what was hit, band-integrated once per surface (eq. 48).
  std::vector<double> object_radiance(frame.objects.size(), -1.0);
  frame.scene_radiance.assign(directions.size(), 0.0);
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const geometry::Hit& hit = frame.hits[i];
    if (hit.object_id < 0) continue;  // the sky: no background terms yet
    double& L = object_radiance[static_cast<std::size_t>(hit.object_id)];
    if (L < 0) L = effective_radiance(frame.objects[static_cast<std::size_t>(hit.object_id)].surface, frame.spectral);
    frame.scene_radiance[i] = L;
  }
}

}  // namespace eoir::scene
