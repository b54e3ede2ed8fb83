// Dynamic metrics involving a target (spec 5.13, Table 2): point or extended
// classification by the target solid angle against the effective IFOV solid
// angle, signal, noise and SNR (eqs. 58-78), evaluated without rendering a
// frame: one line of sight for point targets, a small window of samples
// around the target for extended ones (DESIGN.md 4: model no more than the
// report needs).
#pragma once
#include <string>

#include "core/time.hpp"
#include "sensor/static_metrics.hpp"
#include "universe/universe.hpp"

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
  // Where the target is on the focal plane: pixel coordinates with 0 at the
  // centre of pixel 0 (columns toward body -x, rows toward body -y).
  double pixel_x = 0, pixel_y = 0;
  bool in_field = false;
};

// Throws eoir::Error: unknown sensor/target names, a target equal to the
// sensor or its parent (not_allowed), a target that images nothing, no state.
TargetMetrics target_metrics(const universe::Universe& universe, const EngineTime& t,
                             const universe::Object& sensor, const sensor::StaticMetrics& m,
                             const std::string& target);

}  // namespace eoir::metrics
