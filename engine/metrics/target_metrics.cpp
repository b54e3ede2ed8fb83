#include "metrics/target_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "scene/apparent_grid.hpp"

namespace eoir::metrics {
namespace {
using geometry::Vec3;

// The radiance a hit along the unit direction d sees (the sky's where it meets nothing).
double radiance_of(const scene::World& world, const geometry::Hit& hit, const Vec3& d) {
  if (hit.object_id < 0) return world.sky_radiance(d);
  const scene::WorldObject& o = *world.objects[static_cast<std::size_t>(hit.object_id)];
  return o.radiance_at(hit.part, hit.point_body_m, o.direction_to_body(hit.normal_frame), hit.facet);
}

// Eqs. 59-71 of a point target of irradiance E_tgt against the background
// radiance L_bkg, the target filling omega_ratio of the effective IFOV.
void point_target_terms(const sensor::StaticMetrics& m, double E_tgt, double L_bkg, double omega_ratio,
                        TargetMetrics& r) {
  const double R_L = m.peak_radiance_responsivity, R_E = m.peak_irradiance_responsivity;
  const double ne_dark = m.dark_noise_electrons, SEe = m.saturation_electrons;
  const double r_tgt = std::min(E_tgt * R_E + L_bkg * (1.0 - omega_ratio) * R_L, SEe);  // eq. 59
  const double r_bkg = std::min(L_bkg * R_L, SEe);                                     // eq. 60
  const double sigma = std::sqrt(ne_dark * ne_dark + L_bkg * R_L);                     // eq. 64
  r.effective_target_irradiance_W_cm2 = E_tgt;
  r.effective_background_radiance_W_cm2_sr = L_bkg;
  r.scene_photon_nei_W_cm2 = std::sqrt(L_bkg * R_L) / R_E;  // eq. 70
  r.total_nei_W_cm2 = sigma / R_E;                          // eq. 69
  // Table 2 notes: NER from NEI through the equal noise electrons.
  r.scene_photon_ner_W_cm2_sr = r.scene_photon_nei_W_cm2 * R_E / R_L;
  r.total_ner_W_cm2_sr = r.total_nei_W_cm2 * R_E / R_L;
  r.snr = r.visible ? std::fabs(r_tgt - r_bkg) / sigma : 0.0;  // eq. 65
}

// Visible: some line of sight toward one of the target's parts (each part's
// origin lies inside it) meets the target before anything else.
bool unobstructed(const scene::World& world, const scene::WorldObject& target) {
  for (const geometry::ShapePart& part : target.seen.parts) {
    const Vec3 centre = target.seen.position_m + target.seen.body_to_frame * part.offset_m;
    if (centre.norm() == 0) continue;
    if (world.caster.cast(centre.normalized()).object_id == target.id) return true;
  }
  return false;
}
}  // namespace

const scene::WorldObject& find_target(const scene::World& world, const universe::Universe& universe,
                                      const std::string& target_name) {
  const universe::Object& target = universe.get(target_name, "target");
  const universe::Object& sensor = universe.sensor(world.sensor_name);
  if (target.name == sensor.name || target.name == sensor.parent)
    throw Error(Status::not_allowed,
                "target: '" + target_name + "' is the sensor or its parent, which the sensor cannot see");
  const scene::WorldObject* w = world.find(target_name);
  if (!w)
    throw Error(Status::not_allowed, "target: '" + target_name + "' images nothing (shape none, a sensor or the "
                                     "star field) or has no state");
  return *w;
}

TargetMetrics target_metrics(const scene::World& world, const sensor::SensorModel& sensor,
                             const scene::WorldObject& tp) {
  const universe::SensorParameters& p = sensor.parameters;
  const sensor::StaticMetrics& m = sensor.metrics;
  TargetMetrics r;
  const double range_m = tp.range_m;
  r.range_km = range_m / 1e3;
  r.geometric_ifov_footprint_m2 = m.ifov_solid_angle_sr * range_m * range_m;      // Table 2
  r.effective_ifov_footprint_m2 = m.effective_ifov_solid_angle_sr * range_m * range_m;
  r.target_solid_angle_sr = tp.projected_area_m2() / (range_m * range_m);         // eq. 58
  r.point_source = r.target_solid_angle_sr < m.effective_ifov_solid_angle_sr;       // 5.13.1, 5.13.3

  // Where the target is in the field (its body origin; a point source where
  // it appears, as the image has it: scene/apparent_grid.hpp).
  const geometry::SampleGrid& grid = world.grid();
  scene::GridPlace place;
  if (scene::ApparentGrid(world).object(tp, place)) {
    r.pixel_x = grid.pixel_x_of(place.column);
    r.pixel_y = grid.pixel_y_of(place.row);
    r.in_field = r.pixel_x >= -0.5 && r.pixel_x <= p.horizontal_pixels - 0.5 && r.pixel_y >= -0.5 &&
                 r.pixel_y <= p.vertical_pixels - 0.5;
  }
  r.visible = r.in_field && unobstructed(world, tp);
  const Vec3 los = tp.seen.position_m.normalized();  // where the observer's rays meet it

  const double R_L = m.peak_radiance_responsivity;
  const double ne_dark = m.dark_noise_electrons, SEe = m.saturation_electrons;
  if (r.point_source) {
    // Background: what the line of sight meets beyond the target (eq. 62).
    const double L_bkg = radiance_of(world, world.caster.cast(los, geometry::RayQuery{geometry::ray_mask_all, tp.id}), los);
    r.point_target_solid_angle_sr = r.target_solid_angle_sr;
    point_target_terms(m, tp.point_irradiance_W_cm2() /* eq. 61 */, L_bkg,
                       r.target_solid_angle_sr / m.effective_ifov_solid_angle_sr, r);
    return r;
  }
  // Extended target (5.13.3): average radiances over the samples of a
  // rectangle around the target, on the sensor's sample spacing (at most
  // (2n+1)^2 samples, n = target_window_max_half_samples; coarser for
  // targets that would need more).
  const Fidelity& f = sensor.fidelity();
  const double angular_radius = std::asin(std::min(1.0, tp.bounding_radius_m / range_m));
  const double sample = grid.sample_angle_rad();
  const double extent = f.target_window_extent * angular_radius;
  const int half = std::clamp(static_cast<int>(std::ceil(extent / sample)), 2,
                              static_cast<int>(f.target_window_max_half_samples));
  const double step = extent / half;
  Vec3 u = los.cross(std::fabs(los.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX()).normalized();
  const Vec3 v = los.cross(u);
  std::vector<Vec3> directions;
  for (int j = -half; j <= half; ++j)
    for (int i = -half; i <= half; ++i) directions.push_back((los + std::tan(i * step) * u + std::tan(j * step) * v).normalized());
  std::vector<geometry::Hit> hits;
  world.caster.cast(directions, hits, 1);
  double sum_tgt = 0, sum_bkg = 0;
  int n_tgt = 0, n_bkg = 0;
  for (std::size_t k = 0; k < hits.size(); ++k) {
    const geometry::Hit& h = hits[k];
    const double L = radiance_of(world, h, directions[k]);
    if (h.object_id == tp.id) sum_tgt += L, ++n_tgt;
    else sum_bkg += L, ++n_bkg;
  }
  r.visible = r.visible || (r.in_field && n_tgt > 0);
  const double L_tgt = n_tgt ? sum_tgt / n_tgt : 0.0;  // eq. 72, 74
  const double L_bkg = n_bkg ? sum_bkg / n_bkg : 0.0;  // eq. 73, 75
  const double SER = SEe / R_L;
  const double L_signal = std::fabs(std::min(L_tgt, SER) - std::min(L_bkg, SER));  // eq. "30" of 5.13.3
  const double ner_dark = ne_dark / R_L;
  r.effective_target_radiance_W_cm2_sr = L_tgt;
  r.effective_background_radiance_W_cm2_sr = L_bkg;
  r.scene_photon_ner_W_cm2_sr = std::sqrt(L_bkg / R_L);                                          // eq. 78
  r.total_ner_W_cm2_sr = std::sqrt(ner_dark * ner_dark + r.scene_photon_ner_W_cm2_sr * r.scene_photon_ner_W_cm2_sr);  // eq. 77
  // Table 2 notes: NEI from NER through the equal noise electrons.
  r.scene_photon_nei_W_cm2 = r.scene_photon_ner_W_cm2_sr * R_L / m.peak_irradiance_responsivity;
  r.total_nei_W_cm2 = r.total_ner_W_cm2_sr * R_L / m.peak_irradiance_responsivity;
  r.snr = r.visible ? L_signal / r.total_ner_W_cm2_sr : 0.0;  // eq. 76
  return r;
}

TargetMetrics star_metrics(const scene::World& world, const sensor::SensorModel& sensor, const scene::WorldStar& star) {
  TargetMetrics r;
  const geometry::SampleGrid& grid = world.grid();
  r.point_source = true;
  r.pixel_x = grid.pixel_x_of(star.column);
  r.pixel_y = grid.pixel_y_of(star.row);
  r.in_field = r.visible = true;  // the sky holds the stars in the field that nothing hides
  point_target_terms(sensor.metrics, star.irradiance_W_cm2, world.sky_radiance(star.direction_j2000), 0.0, r);
  return r;
}

}  // namespace eoir::metrics
