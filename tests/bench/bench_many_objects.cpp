// Frame time against the number of objects (issue 23 items 3 and 7): a GEO
// belt seen by a ground telescope. The engine's object limits are raised
// (README "Object limits") to hold N satellites beyond 16; up to 16 the
// engine keeps the default profile, as the spec's engine renders them.
//
// Scene: 2010-06-21T00:00:00Z (midnight at longitude 0; at the solstice the
// Earth's shadow passes 23 deg south of the belt, so every GEO satellite is
// sunlit). The Earth (atmosphere off) and a site on the equator at longitude
// 0 carrying "Sensor", pointed at the zenith: 256 x 256 pixels over a
// 10 deg field, 0.45-0.75 um, 10 spectral intervals, coarse mode, noise on.
// N satellites, 2 x 1 x 1 m boxes at 290 K, on circular equatorial orbits of
// the GEO radius (42,164.2 km), their states pushed at the frame time.
//
//  - BM_GeoBelt/N/0: the N satellites evenly spaced around the whole belt;
//    the field holds the ~8.5 deg of the belt around the meridian (about
//    2.4 % of them: 24 of 1,000), the rest is culled.
//  - BM_GeoBelt/N/1: all N within the field (longitudes within +-3.5 deg of
//    the site's, evenly spaced): every one a point source in the image and a
//    truth row.
//
// Each iteration moves the engine time on by 1 s (a new world: placing,
// culling and shading every object again) and renders, so the time is a
// whole frame of a sequence, truth included. Counters: frame_ms (the mean
// wall time), world_and_truth_ms (frame less the scene and sensor stages),
// truth_rows, point_sources, and ratio_to_16 (this case's frame against
// BM_GeoBelt/16/<same layout>, measured in the same process just before;
// issue 23: at most 2 at N = 1,000 for the whole belt).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "engine.hpp"
#include "universe/object_motion.hpp"
#include "universe/pointing.hpp"

namespace {

using eoir::Engine;
using eoir::EngineTime;
using eoir::Value;
namespace universe = eoir::universe;

constexpr double kGeoRadius_m = 42164.2e3;
constexpr double kPi = 3.14159265358979323846;

EngineTime epoch() { return EngineTime::from(eoir::utc_from_iso("2010-06-21T00:00:00Z")); }

std::unique_ptr<Engine> make_belt(std::int64_t n, bool in_field) {
  eoir::EngineOptions opt;
  opt.seed = 1;
  auto e = std::make_unique<Engine>(opt);
  universe::ObjectLimits limits;
  limits.satellites = static_cast<std::size_t>(std::max<std::int64_t>(n, 16));
  e->set_limits(limits);
  e->set_time(epoch());
  e->add_object(universe::ObjectKind::central_body, "Earth");
  e->add_object(universe::ObjectKind::site, "Site");
  e->set_property("Site", "latitude_deg", Value(0.0));
  e->set_property("Site", "longitude_deg", Value(0.0));
  e->add_sensor("Sensor", "Site");
  e->set_property("Sensor", "horizontal_pixels", Value(std::int64_t{256}));
  e->set_property("Sensor", "vertical_pixels", Value(std::int64_t{256}));
  e->set_property("Sensor", "horizontal_fov_deg", Value(10.0));
  e->set_property("Sensor", "vertical_fov_deg", Value(10.0));
  e->set_property("Sensor", "band_low_um", Value(0.45));
  e->set_property("Sensor", "band_high_um", Value(0.75));
  e->set_property("Sensor", "spectral_intervals", Value(std::int64_t{10}));
  e->set_property("Sensor", "diffraction_wavelength_um", Value(0.6));
  e->set_property("Sensor", "focal_length_cm", Value(10.0));
  e->set_property("Sensor", "f_number", Value(2.0));
  e->set_property("Sensor", "scene_mode", Value(std::string("coarse")));
  e->set_property("Sensor", "noise_enabled", Value(true));
  // The site's meridian in J2000 at the epoch: the site's position.
  const universe::Kinematics site = universe::kinematics_at(e->universe(), e->universe().get("Site"), e->time());
  const double site_angle = std::atan2(site.position_m.y(), site.position_m.x());
  const double speed = std::sqrt(3.986004418e14 / kGeoRadius_m);
  for (std::int64_t i = 0; i < n; ++i) {
    const std::string name = "Geo" + std::to_string(i);
    const double spacing = in_field ? 7.0 * kPi / 180.0 / static_cast<double>(n) : 2.0 * kPi / static_cast<double>(n);
    const double a = site_angle + (in_field ? -3.5 * kPi / 180.0 : 0.0) + (static_cast<double>(i) + 0.5) * spacing;
    e->add_object(universe::ObjectKind::satellite, name);
    e->set_property(name, "shape", Value(std::string("box")));
    e->set_property(name, "dimensions_m", Value(std::vector<double>{2.0, 1.0, 1.0}));
    e->set_property(name, "temperature_K", Value(290.0));
    const double r[3] = {kGeoRadius_m * std::cos(a), kGeoRadius_m * std::sin(a), 0.0};
    const double v[3] = {-speed * std::sin(a), speed * std::cos(a), 0.0};
    const double q[4] = {1, 0, 0, 0};
    e->push_state(name, e->time(), 0, r, v, q);
  }
  const universe::PushedState p =
      universe::azimuth_elevation_pointing(e->universe(), e->universe().sensor("Sensor"), e->time(), 0.0, 90.0);
  const double zero[3] = {0, 0, 0};
  const double q[4] = {p.attitude.w(), p.attitude.x(), p.attitude.y(), p.attitude.z()};
  const double w[3] = {p.angular_velocity_rad_s.x(), p.angular_velocity_rad_s.y(), p.angular_velocity_rad_s.z()};
  e->push_state("Sensor", p.epoch, p.frame == universe::StateFrame::j2000 ? 0 : 1, zero, zero, q, w);
  return e;
}

struct FrameCost {
  double frame_s = 0, stages_s = 0;
  std::size_t truth = 0, point_sources = 0;
};

// One frame of `e`, 1 s after its last.
FrameCost next_frame(Engine& e) {
  FrameCost c;
  const auto t0 = std::chrono::steady_clock::now();
  e.set_time(e.time().plus_seconds(1.0));
  const eoir::Frame& f = e.render("Sensor");
  c.frame_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const eoir::FrameTimings& t = f.timings;
  c.stages_s = t.ray_casting_s + t.shading_s + t.convolution_s + t.point_sources_s + t.noise_s + t.display_s;
  c.truth = f.truth.size();
  c.point_sources = f.scene.image.point_sources.size();
  return c;
}

// The mean frame time of BM_GeoBelt/16/layout, measured once per process.
double reference_frame_s(bool in_field) {
  static std::map<bool, double> cache;
  auto it = cache.find(in_field);
  if (it != cache.end()) return it->second;
  auto e = make_belt(16, in_field);
  next_frame(*e);  // tables and plans
  double sum = 0;
  const int frames = 5;
  for (int i = 0; i < frames; ++i) sum += next_frame(*e).frame_s;
  return cache[in_field] = sum / frames;
}

void BM_GeoBelt(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const bool in_field = state.range(1) != 0;
  const double reference_s = reference_frame_s(in_field);
  auto e = make_belt(n, in_field);
  next_frame(*e);  // the one-off tables, as the reference's
  FrameCost sum;
  int frames = 0;
  for (auto _ : state) {
    const FrameCost c = next_frame(*e);
    sum.frame_s += c.frame_s;
    sum.stages_s += c.stages_s;
    sum.truth = c.truth;
    sum.point_sources = c.point_sources;
    ++frames;
  }
  state.counters["frame_ms"] = 1e3 * sum.frame_s / frames;
  state.counters["world_and_truth_ms"] = 1e3 * (sum.frame_s - sum.stages_s) / frames;
  state.counters["truth_rows"] = static_cast<double>(sum.truth);
  state.counters["point_sources"] = static_cast<double>(sum.point_sources);
  state.counters["ratio_to_16"] = sum.frame_s / frames / reference_s;
}
BENCHMARK(BM_GeoBelt)
    ->ArgsProduct({{1, 16, 100, 300, 1000, 10000}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
