#include "scene/scene_generator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "scene/placement.hpp"
#include "scene/surface_shader.hpp"
#include "universe/object_motion.hpp"

namespace eoir::scene {
namespace {
using geometry::Vec3;

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

}  // namespace

void generate_scene(const universe::Universe& universe, const EngineTime& t, const universe::Object& sensor,
                    const sensor::StaticMetrics& metrics, unsigned threads, Frame& frame) {
  using clock = std::chrono::steady_clock;
  const auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  const auto t0 = clock::now();
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
  std::vector<geometry::PlacedObject>& placed = frame.placed;
  placed.clear();
  for (const universe::Object& o : universe.objects()) {
    if (o.name == sensor.parent) continue;  // a sensor never images its parent (4.1.5.1)
    std::optional<Placement> pl =
        place_object(universe, o, t, observer.position_m, static_cast<std::int32_t>(frame.objects.size()));
    if (!pl) continue;
    if (outside_view(j2000_to_body * pl->placed.position_m, pl->bounding_radius_m, grid)) continue;  // culled
    tessellate_placement(o, *pl);
    frame.objects.push_back(pl->surface);
    const double range = pl->range_m, radius = pl->bounding_radius_m;
    if (range > radius && 2.0 * std::asin(std::min(1.0, radius / range)) < sample_angle_rad) {
      // A distant area source smaller than a sample (spec 4.1.6.1), imaged
      // as a point where it lies inside the ideal field of view (5.2, 7.2.1).
      double c = 0, r = 0;
      if (!grid.sample_of(j2000_to_body * pl->placed.position_m, c, r)) continue;
      const double g = static_cast<double>(grid.guard_samples()), tol = 1e-4;
      const bool inside = c >= g - 0.5 - tol && c <= g + 4.0 * grid.pixels_x - 0.5 + tol &&
                          r >= g - 0.5 - tol && r <= g + 4.0 * grid.pixels_y - 0.5 + tol;
      if (inside)
        frame.point_sources.push_back(
            PointSource{pl->placed.object_id, c, r, point_irradiance_W_cm2(*pl, frame.spectral)});
      continue;
    }
    placed.push_back(std::move(pl->placed));
  }

  std::vector<const geometry::PlacedObject*> placed_by_id(frame.objects.size(), nullptr);
  for (const geometry::PlacedObject& po : placed) placed_by_id[static_cast<std::size_t>(po.object_id)] = &po;
  const auto t1 = clock::now();
  // 3-5. Ray-cast the sample grid (spec 4.1.3) in the observer frame and
  // shade only what is hit (eq. 48): one radiance per part of a uniform
  // surface; per patch (coarse) or per sample point (smooth) where the
  // temperature varies (scene/surface_shader.hpp).
  const std::int64_t w = grid.width(), h = grid.height();
  const std::size_t count = static_cast<std::size_t>(w * h);
  const bool smooth = frame.smooth = p.scene_mode == "smooth";
  std::vector<std::unique_ptr<SurfaceShader>> shaders(frame.objects.size());
  for (const geometry::PlacedObject& po : placed)
    shaders[static_cast<std::size_t>(po.object_id)] =
        std::make_unique<SurfaceShader>(frame.objects[static_cast<std::size_t>(po.object_id)], po, frame.spectral, smooth);
  const auto t2 = clock::now();
  frame.samples.assign(count, Frame::SampleHit{});
  frame.scene_radiance.assign(count, 0.0);
  const auto direction = [&](std::size_t i) {
    const auto r = static_cast<std::int64_t>(i) / w, c = static_cast<std::int64_t>(i) % w;
    return Vec3(frame.body_to_j2000 * grid.direction_body(c, r));
  };
  geometry::RayCaster caster;
  caster.build(placed);
  caster.cast_objects(
      count, direction,
      [&](std::size_t i, std::int32_t object, std::int32_t part, double range_m) {
        frame.samples[i] = Frame::SampleHit{object, part};
        if (object < 0) return;
        const SurfaceShader& shader = *shaders[static_cast<std::size_t>(object)];
        if (!shader.varying()) {
          frame.scene_radiance[i] = shader.part_radiance(part);
          return;
        }
        const geometry::PlacedObject& po = *placed_by_id[static_cast<std::size_t>(object)];
        const Vec3 point_body = po.body_to_frame.transpose() * (range_m * direction(i) - po.position_m);
        frame.scene_radiance[i] = shader.radiance_at(part, point_body);
      },
      threads);
  const auto t3 = clock::now();
  frame.timings.setup_s = seconds(t0, t1);
  frame.timings.shading_s = seconds(t1, t2);  // band integration per surface; the per-sample lookup rides with the casts
  frame.timings.ray_casting_s = seconds(t2, t3);
  frame.timings.rays = count;
}

}  // namespace eoir::scene
