#include "metrics/target_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "scene/placement.hpp"
#include "scene/sample_grid.hpp"
#include "scene/surface_shader.hpp"
#include "universe/object_motion.hpp"

namespace eoir::metrics {
namespace {
using geometry::Vec3;

struct World {
  std::vector<scene::Placement> placements;  // every imageable object but the sensor's parent
  int target = -1;                           // index into placements
};

World place_world(const universe::Universe& universe, const EngineTime& t, const universe::Object& sensor,
                  const Vec3& observer, const std::string& target) {
  World w;
  for (const universe::Object& o : universe.objects()) {
    if (o.name == sensor.parent) continue;
    auto pl = scene::place_object(universe, o, t, observer, static_cast<std::int32_t>(w.placements.size()));
    if (!pl) continue;
    scene::tessellate_placement(o, *pl);
    if (o.name == target) w.target = static_cast<int>(w.placements.size());
    w.placements.push_back(std::move(*pl));
  }
  return w;
}

// Casts `directions` against the world, with or without the target.
std::vector<geometry::Hit> cast(const World& w, bool with_target, const std::vector<Vec3>& directions) {
  std::vector<geometry::PlacedObject> objects;
  for (size_t i = 0; i < w.placements.size(); ++i)
    if (with_target || static_cast<int>(i) != w.target) objects.push_back(w.placements[i].placed);
  geometry::RayCaster caster;
  caster.build(objects);
  std::vector<geometry::Hit> hits;
  caster.cast(directions, hits, 1);
  return hits;
}

// The radiance a hit sees (the sky: no background terms yet).
double radiance_of(const std::vector<scene::SurfaceShader>& shaders, const geometry::Hit& hit) {
  if (hit.object_id < 0) return 0.0;
  return shaders[static_cast<size_t>(hit.object_id)].radiance_at(hit.part, hit.point_body_m);
}
}  // namespace

TargetMetrics target_metrics(const universe::Universe& universe, const EngineTime& t,
                             const universe::Object& sensor, const sensor::StaticMetrics& m,
                             const std::string& target_name) {
  const universe::Object& target = universe.get(target_name, "target");
  if (target.name == sensor.name || target.name == sensor.parent)
    throw Error(Status::not_allowed,
                "target: '" + target_name + "' is the sensor or its parent, which the sensor cannot see");
  const sensor::SensorParameters& p = sensor.sensor;
  const universe::Kinematics observer = universe::kinematics_at(universe, sensor, t);
  World w = place_world(universe, t, sensor, observer.position_m, target_name);
  if (w.target < 0)
    throw Error(Status::not_allowed, "target: '" + target_name + "' images nothing (shape none, a sensor or the "
                                     "star field) or has no state");
  const scene::Placement& tp = w.placements[static_cast<size_t>(w.target)];
  const scene::SpectralView view = scene::SpectralView::make(
      p.band_low_um, p.band_high_um, p.spectral_intervals,
      p.band_integration == "exact" ? scene::BandIntegration::exact : scene::BandIntegration::grid);

  std::vector<scene::SurfaceShader> shaders;
  for (const scene::Placement& pl : w.placements) shaders.emplace_back(pl.surface, pl.placed, view, p.scene_mode == "smooth");

  TargetMetrics r;
  const double range_m = tp.range_m;
  r.range_km = range_m / 1e3;
  r.geometric_ifov_footprint_m2 = m.ifov_solid_angle_sr * range_m * range_m;      // Table 2
  r.effective_ifov_footprint_m2 = m.effective_ifov_solid_angle_sr * range_m * range_m;
  r.target_solid_angle_sr = scene::projected_solid_angle_sr(tp);                    // eq. 58
  r.point_source = r.target_solid_angle_sr < m.effective_ifov_solid_angle_sr;       // 5.13.1, 5.13.3

  // Where the target is in the field (its body origin).
  const Eigen::Matrix3d to_body = observer.attitude.toRotationMatrix().transpose();
  const scene::SampleGrid grid = scene::make_sample_grid(p, m);
  double c = 0, row = 0;
  if (grid.sample_of(to_body * tp.placed.position_m, c, row)) {
    const double g = static_cast<double>(grid.guard_samples());
    r.pixel_x = (c - g + 0.5) / scene::SampleGrid::per_pixel - 0.5;
    r.pixel_y = (row - g + 0.5) / scene::SampleGrid::per_pixel - 0.5;
    r.in_field = r.pixel_x >= -0.5 && r.pixel_x <= p.horizontal_pixels - 0.5 && r.pixel_y >= -0.5 &&
                 r.pixel_y <= p.vertical_pixels - 0.5;
  }
  // Visible: in the field and the line of sight to the target's centre meets
  // the target first.
  const Vec3 los = tp.placed.position_m.normalized();
  const std::vector<geometry::Hit> first = cast(w, true, {los});
  r.visible = r.in_field && first[0].object_id == tp.placed.object_id;

  const double R_L = m.peak_radiance_responsivity, R_E = m.peak_irradiance_responsivity;
  const double ne_dark = m.dark_noise_electrons, SEe = m.saturation_electrons;
  if (r.point_source) {
    // Background: what the line of sight meets beyond the target (eq. 62).
    const double L_bkg = radiance_of(shaders, cast(w, false, {los})[0]);
    const double E_tgt = scene::point_irradiance_W_cm2(tp, view);  // eq. 61
    const double omega_ratio = r.target_solid_angle_sr / m.effective_ifov_solid_angle_sr;
    const double r_tgt = std::min(E_tgt * R_E + L_bkg * (1.0 - omega_ratio) * R_L, SEe);  // eq. 59
    const double r_bkg = std::min(L_bkg * R_L, SEe);                                     // eq. 60
    const double sigma = std::sqrt(ne_dark * ne_dark + L_bkg * R_L);                     // eq. 64
    r.effective_target_irradiance_W_cm2 = E_tgt;
    r.point_target_solid_angle_sr = r.target_solid_angle_sr;
    r.effective_background_radiance_W_cm2_sr = L_bkg;
    r.scene_photon_nei_W_cm2 = std::sqrt(L_bkg * R_L) / R_E;  // eq. 70
    r.total_nei_W_cm2 = sigma / R_E;                          // eq. 69
    // Table 2 notes: NER from NEI through the equal noise electrons.
    r.scene_photon_ner_W_cm2_sr = r.scene_photon_nei_W_cm2 * R_E / R_L;
    r.total_ner_W_cm2_sr = r.total_nei_W_cm2 * R_E / R_L;
    r.snr = r.visible ? std::fabs(r_tgt - r_bkg) / sigma : 0.0;  // eq. 65
    return r;
  }
  // Extended target (5.13.3): average radiances over the samples of a
  // rectangle around the target, on the sensor's sample spacing (at most
  // 128 x 128 samples; coarser for targets that would need more).
  const double angular_radius = std::asin(std::min(1.0, tp.bounding_radius_m / range_m));
  const double sample = std::min(grid.pitch_x_cm, grid.pitch_y_cm) / scene::SampleGrid::per_pixel / p.focal_length_cm;
  const int half = std::clamp(static_cast<int>(std::ceil(1.5 * angular_radius / sample)), 2, 64);
  const double step = 1.5 * angular_radius / half;
  Vec3 u = los.cross(std::fabs(los.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX()).normalized();
  const Vec3 v = los.cross(u);
  std::vector<Vec3> directions;
  for (int j = -half; j <= half; ++j)
    for (int i = -half; i <= half; ++i) directions.push_back((los + std::tan(i * step) * u + std::tan(j * step) * v).normalized());
  const std::vector<geometry::Hit> hits = cast(w, true, directions);
  double sum_tgt = 0, sum_bkg = 0;
  int n_tgt = 0, n_bkg = 0;
  for (const auto& h : hits) {
    const double L = radiance_of(shaders, h);
    if (h.object_id == tp.placed.object_id) sum_tgt += L, ++n_tgt;
    else sum_bkg += L, ++n_bkg;
  }
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
  r.scene_photon_nei_W_cm2 = r.scene_photon_ner_W_cm2_sr * R_L / R_E;
  r.total_nei_W_cm2 = r.total_ner_W_cm2_sr * R_L / R_E;
  r.snr = r.visible ? L_signal / r.total_ner_W_cm2_sr : 0.0;  // eq. 76
  return r;
}

}  // namespace eoir::metrics
