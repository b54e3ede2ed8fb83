// Scenes shared by the benchmarks: a sensor on a GEO-radius satellite looking
// at the Earth (the Moon in the universe, LEO satellites in the field), built
// directly on eoir::Engine.
#pragma once
#include <sys/resource.h>

#include <cmath>
#include <memory>
#include <string>

#include "engine.hpp"
#include "universe/pointing.hpp"

namespace eoir::bench {

// 2010-03-30T02:25:00Z (the spec 6.1.1 V_Test1 epoch): the Sun is near +x
// J2000, so a sensor on +x sees the day side.
inline EngineTime bench_epoch() { return EngineTime::from(utc_from_iso("2010-03-30T02:25:00Z")); }

// Peak resident set size of this process so far, MiB (getrusage: KiB on Linux).
inline double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

// A satellite (shape/dimensions/temperature) at J2000 position `pos_m`.
inline void add_satellite(Engine& e, const std::string& name, const std::string& shape,
                          const std::vector<double>& dims, double temperature_K, const double pos_m[3],
                          const double vel_m_s[3]) {
  e.add_object(universe::ObjectKind::satellite, name);
  e.set_property(name, "shape", Value(shape));
  if (shape != "none") {
    e.set_property(name, "dimensions_m", Value(dims));
    e.set_property(name, "temperature_K", Value(temperature_K));
    e.set_property(name, "reflectance", Value(0.2));
  }
  const double q[4] = {1, 0, 0, 0};
  e.push_state(name, e.time(), 0, pos_m, vel_m_s, q);
}

struct SensorSetup {
  std::int64_t pixels = 256;
  double fov_deg = 20.0;
  std::int64_t intervals = 10;
  std::string band_integration = "grid";
  bool noise = true;
  double band_low_um = 8.0, band_high_um = 12.0;
  std::string scene_mode = "coarse";
  bool day_side = true;  // false: the host and the LEO satellites on the night side (no sunlight on the scene)
  std::string atmosphere = "none";  // the Earth's `atmosphere` (issue 20)
};

// A sensor named `name` on `parent`, looking along `look` (J2000 unit vector;
// body +z goes there).
inline void add_sensor(Engine& e, const std::string& name, const std::string& parent, const SensorSetup& s,
                       const Eigen::Vector3d& look) {
  e.add_sensor(name, parent);
  e.set_property(name, "horizontal_pixels", Value(s.pixels));
  e.set_property(name, "vertical_pixels", Value(s.pixels));
  e.set_property(name, "horizontal_fov_deg", Value(s.fov_deg));
  e.set_property(name, "vertical_fov_deg", Value(s.fov_deg));
  e.set_property(name, "band_low_um", Value(s.band_low_um));
  e.set_property(name, "band_high_um", Value(s.band_high_um));
  e.set_property(name, "scene_mode", Value(s.scene_mode));
  e.set_property(name, "spectral_intervals", Value(s.intervals));
  e.set_property(name, "focal_length_cm", Value(10.0));
  e.set_property(name, "f_number", Value(2.0));
  e.set_property(name, "diffraction_wavelength_um", Value(10.0));
  e.set_property(name, "band_integration", Value(s.band_integration));
  e.set_property(name, "noise_enabled", Value(s.noise));
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), look.normalized());
  const double qa[4] = {q.w(), q.x(), q.y(), q.z()};
  const double zero[3] = {0, 0, 0};
  e.push_state(name, e.time(), 0, zero, zero, qa);
}

// The frame scene: Earth, Moon, a GEO-radius host on +x J2000 (the day side;
// -x with day_side false) carrying "Sensor" (looking at the Earth's centre),
// and three LEO satellites (two 2 m spheres and a 2 x 1 x 1 m box) between it
// and the Earth, inside the field (sunlit by day, in the Earth's shadow by night).
inline std::unique_ptr<Engine> make_geo_scene(const SensorSetup& s, std::uint64_t seed = 1, std::uint32_t threads = 0) {
  EngineOptions opt;
  opt.seed = seed;
  opt.threads = threads;
  auto e = std::make_unique<Engine>(opt);
  e->set_time(bench_epoch());
  e->add_object(universe::ObjectKind::central_body, "Earth");
  e->add_object(universe::ObjectKind::central_body, "Moon");
  const double x = s.day_side ? 1.0 : -1.0;  // the Sun is near +x
  const double host[3] = {x * 42164.2e3, 0, 0}, host_v[3] = {0, 3074.7, 0};
  add_satellite(*e, "Host", "none", {}, 0, host, host_v);
  const double p1[3] = {x * 6978e3, 1200e3, 400e3}, p2[3] = {x * 7000e3, -900e3, -1500e3},
               p3[3] = {x * 6900e3, 300e3, -2000e3};
  const double v1[3] = {0, 0, 7500}, v2[3] = {0, 7500, 0}, v3[3] = {0, 5300, 5300};
  add_satellite(*e, "Leo1", "sphere", {1.0}, 300.0, p1, v1);
  add_satellite(*e, "Leo2", "sphere", {1.0}, 280.0, p2, v2);
  add_satellite(*e, "Leo3", "box", {2.0, 1.0, 1.0}, 320.0, p3, v3);
  add_sensor(*e, "Sensor", "Host", s, -x * Eigen::Vector3d::UnitX());
  e->set_property("Earth", "atmosphere", Value(s.atmosphere));
  return e;
}

// A ground telescope: a site at 30 N 150 E (by day, the Sun some 60 deg up
// at the bench epoch; 30 W with day_side false: night), "Sensor" pointed at
// azimuth 270, elevation 30.
inline std::unique_ptr<Engine> make_ground_scene(const SensorSetup& s, std::uint64_t seed = 1) {
  EngineOptions opt;
  opt.seed = seed;
  auto e = std::make_unique<Engine>(opt);
  e->set_time(bench_epoch());
  e->add_object(universe::ObjectKind::central_body, "Earth");
  e->add_object(universe::ObjectKind::site, "Site");
  e->set_property("Site", "latitude_deg", Value(30.0));
  e->set_property("Site", "longitude_deg", Value(s.day_side ? 150.0 : -30.0));
  add_sensor(*e, "Sensor", "Site", s, Eigen::Vector3d::UnitZ());
  const universe::PushedState p =
      universe::azimuth_elevation_pointing(e->universe(), e->universe().sensor("Sensor"), e->time(), 270.0, 30.0);
  const double zero[3] = {0, 0, 0};
  const double q[4] = {p.attitude.w(), p.attitude.x(), p.attitude.y(), p.attitude.z()};
  const double w[3] = {p.angular_velocity_rad_s.x(), p.angular_velocity_rad_s.y(), p.angular_velocity_rad_s.z()};
  e->push_state("Sensor", p.epoch, p.frame == universe::StateFrame::j2000 ? 0 : 1, zero, zero, q, w);
  e->set_property("Earth", "atmosphere", Value(s.atmosphere));
  return e;
}

}  // namespace eoir::bench
