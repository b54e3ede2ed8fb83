// Dynamic metrics involving a target (spec 5.13, Table 2): point or extended
// classification by the target solid angle against the effective IFOV solid
// angle, signal, noise and SNR (eqs. 58-78), evaluated on the sensor's world
// without rendering a frame: a few lines of sight for point targets, a small
// window of samples around the target for extended ones (DESIGN section 4:
// model no more than the report needs).
#pragma once
#include <cstdint>
#include <string>

#include "scene/world.hpp"
#include "sensor/sensor_model.hpp"

namespace eoir::metrics {

struct TargetMetrics {
  double range_km = 0;
  bool visible = false;           // in the field of view and not hidden by another object
  bool point_source = false;      // Omega_T < Omega_EIFOV (eq. 58, 5.13.1)
  double target_solid_angle_sr = 0;  // Omega_T = A*_T / R^2 (eq. 58), always computed
  // Reported elements (Table 2; zero where the spec says "only defined for").
  double effective_target_irradiance_W_cm2 = 0;  // eq. 61 (point)
  double point_target_solid_angle_sr = 0;        // eq. 58 (point)
  double scene_photon_nei_W_cm2 = 0, total_nei_W_cm2 = 0;            // eqs. 70-71
  double effective_target_radiance_W_cm2_sr = 0;                     // eq. 74 (extended)
  double effective_background_radiance_W_cm2_sr = 0;                 // eq. 62 or 75
  double scene_photon_ner_W_cm2_sr = 0, total_ner_W_cm2_sr = 0;      // eqs. 77-78
  double snr = 0;                                                    // eq. 65 or 76
  double geometric_ifov_footprint_m2 = 0, effective_ifov_footprint_m2 = 0;
  // Where the target's body origin is on the focal plane: pixel coordinates
  // with 0 at the centre of pixel 0 (columns toward body -x, rows toward -y).
  double pixel_x = 0, pixel_y = 0;
  bool in_field = false;
};

// The world object a target names. Throws eoir::Error: unknown name, a
// target equal to the sensor or its parent (not_allowed), a target that
// images nothing or has no state (not_allowed).
const scene::WorldObject& find_target(const scene::World& world, const universe::Universe& universe,
                                      const std::string& target);

// The metrics of `target` (an object of `world`) seen by the world's sensor.
TargetMetrics target_metrics(const scene::World& world, const sensor::SensorModel& sensor,
                             const scene::WorldObject& target);

// The point-target metrics (eqs. 59-71) of a catalogue star of the world's
// sky (range 0: stars are at infinity; no solid angle).
TargetMetrics star_metrics(const scene::World& world, const sensor::SensorModel& sensor, const scene::WorldStar& star);

}  // namespace eoir::metrics
