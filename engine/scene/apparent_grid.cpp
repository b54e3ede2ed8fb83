#include "scene/apparent_grid.hpp"

#include "atmosphere/refraction.hpp"
#include "core/frames.hpp"

namespace eoir::scene {
namespace {
Vec3 up_at(const EngineTime& t, const Vec3& position_j2000) {
  return frames::horizon_at(t, position_j2000).j2000_to_enu.row(2).transpose();
}
}  // namespace

ApparentGrid::ApparentGrid(const World& world)
    : world_(world),
      to_body_(world.observer.body_to_j2000.transpose()),
      to_body_start_(world.observer.body_to_j2000_start.transpose()),
      to_body_end_(world.observer.body_to_j2000_end.transpose()) {
  const WorldAtmosphere& a = world.atmosphere;
  refracting_ = a.on() && a.observer_inside;
  if (!refracting_) return;
  // The zenith turns with the Earth (and moves with an aircraft) during the
  // integration: the world's, changed as the geodetic vertical changes.
  const Observer& o = world.observer;
  const double half = 0.5 * world.view.integration_time_s;
  const Vec3 up = up_at(world.time, o.position_m);
  start_ = end_ = a;
  start_.zenith = (a.zenith + up_at(world.time.plus_seconds(-half), o.position_start_m) - up).normalized();
  end_.zenith = (a.zenith + up_at(world.time.plus_seconds(half), o.position_end_m) - up).normalized();
}

double ApparentGrid::max_refraction_rad() const {
  return refracting_ ? atmosphere::refraction_from_apparent_rad(world_.atmosphere.refraction, 0.0) : 0.0;
}

bool ApparentGrid::star(const Vec3& d, GridPlace& out) const {
  const geometry::SampleGrid& grid = world_.grid();
  out = GridPlace{};
  if (!grid.sample_of(to_body_ * (refracting_ ? world_.atmosphere.apparent_direction(d) : d), out.column, out.row))
    return false;
  // The sensor's rotation during the integration moves the star on the grid.
  double c0 = 0, r0 = 0, c1 = 0, r1 = 0;
  if (grid.sample_of(to_body_start_ * (refracting_ ? start_.apparent_direction(d) : d), c0, r0) &&
      grid.sample_of(to_body_end_ * (refracting_ ? end_.apparent_direction(d) : d), c1, r1)) {
    out.streak_columns = c1 - c0;
    out.streak_rows = r1 - r0;
  }
  return true;
}

bool ApparentGrid::object(const WorldObject& o, GridPlace& out) const {
  const geometry::SampleGrid& grid = world_.grid();
  out = GridPlace{};
  if (!grid.sample_of(to_body_ * o.placed.position_m, out.column, out.row)) return false;
  out.streak_columns = o.streak_columns;
  out.streak_rows = o.streak_rows;
  if (!refracting_ || !(o.refraction_fraction > 0)) return true;
  // The streak's geometric ends, placed as the world places them about the
  // frame-time position, each refracted with the zenith of its instant by
  // the share its distance gives (WorldObject::refraction_fraction).
  const double c = out.column, r = out.row;
  const Vec3 start = world_.observer.body_to_j2000_start *
                     grid.direction_body(c - 0.5 * o.streak_columns, r - 0.5 * o.streak_rows);
  const Vec3 end = world_.observer.body_to_j2000_end *
                   grid.direction_body(c + 0.5 * o.streak_columns, r + 0.5 * o.streak_rows);
  if (!grid.sample_of(to_body_ * o.seen.position_m, out.column, out.row)) return false;
  double c0 = 0, r0 = 0, c1 = 0, r1 = 0;
  if (grid.sample_of(to_body_start_ * start_.apparent_direction(start, o.refraction_fraction), c0, r0) &&
      grid.sample_of(to_body_end_ * end_.apparent_direction(end, o.refraction_fraction), c1, r1)) {
    out.streak_columns = c1 - c0;
    out.streak_rows = r1 - r0;
  }
  return true;
}

}  // namespace eoir::scene
