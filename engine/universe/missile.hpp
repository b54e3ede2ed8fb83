// Missiles and missile systems (spec 4.3.6): up to limits::max_missile_stages
// stages stacked along the missile's body +z axis, each with its timing and
// an optional rocket plume. A missile carries its stages as a JSON array in
// its `missile_stages` property, first (lowest, launched) stage first:
//   [{"length_m": 18, "radius_m": 0.9,          stage body along z in [0, length_m]
//     "parts": [ composite parts (universe/composite.hpp), stage frame: z = 0 at
//                the stage's aft end, +z toward the nose; default a cylinder
//                of radius_m and length_m ],
//     "separation_s": 62,                       from the stage's time 0; omitted = never
//     "drawn_after_separation_s": 10,           a spent stage stays drawn (default 0)
//     "separation_speed_m_s": 5,                ... falling back along -z at this speed
//     "plume": {"temperature_K": 1500 | "spectrum": "name",
//               "length_scale": 4, "width_scale": 1.5, "on_s": 0, "off_s": 62}}, ...]
// Time 0 of the first stage is the launch (the `launch_time_utc` property),
// of each later stage the separation of the one below (spec 4.3.6); the
// separation and the plume's on and off times count from the stage's time 0.
// Only the last stage may omit separation_s.
//
// Placement: the pushed state is that of the missile's body origin, the aft
// end of the lowest stage still attached; the attached stages stack on it
// along +z. A separated stage stays drawn for drawn_after_separation_s, below
// the stack, receding along -z at separation_speed_m_s (relative to the
// stack, in its axes: no gravity or drag of its own). Before the launch the
// whole stack stands without plumes. A stage shows over [time 0 of the
// missile's life, its separation + drawn_after_separation_s); its plume over
// [on_s, off_s) of its own time, while the stage is drawn.
//
// Plume: the shape `plume` (a sphere and its tangent cone) with its sphere's
// centre on the axis at the stage's aft end and the apex along -z; radius
// width_scale x the stage's radius_m, length (sphere's far pole to the apex)
// length_scale x the stage's length_m (defaults 1 and 1); a gray body of
// emittance 0.99 at temperature_K (material gray_body, reflectance 0.01), or
// the named tabulated spectral radiance of the spectrum table instead; a
// plume (any part of shape plume) emits only: it reflects no light.
#pragma once
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/time.hpp"
#include "universe/shapes.hpp"

namespace eoir::universe {

struct Object;

constexpr double plume_emittance = 0.99;  // spec 4.3.6

struct PlumeSettings {
  double length_scale = 1.0;  // plume length / the stage's length
  double width_scale = 1.0;   // plume sphere radius / the stage's radius
  double on_s = 0.0;          // from the stage's time 0
  double off_s = std::numeric_limits<double>::infinity();
  std::optional<double> temperature_K;
  std::string spectrum;  // "" = gray body 0.99 at temperature_K
};

struct MissileStage {
  double length_m = 1.0;
  double radius_m = 0.5;
  std::vector<ShapePart> parts;  // stage frame (z = 0 aft)
  double separation_s = std::numeric_limits<double>::infinity();  // from the stage's time 0
  double drawn_after_separation_s = 0.0;
  double separation_speed_m_s = 0.0;
  std::optional<PlumeSettings> plume;
};

// Parses `missile_stages`. Throws eoir::Error (out_of_range, unknown_name,
// limit_exceeded) naming the JSON path under `field`.
std::vector<MissileStage> parse_missile_stages(const std::string& json_text, const std::string& field);

// Seconds since launch of each stage's time 0 (launch; then each separation).
std::vector<double> stage_start_times_s(const std::vector<MissileStage>& stages);

// The parts in the missile's body frame at `since_launch_s` seconds after
// the launch (NaN: not launched), with the plumes that are on; part_stage
// (if given) receives each part's stage index, plume_part whether it is a plume.
std::vector<ShapePart> missile_parts(const std::vector<MissileStage>& stages, double since_launch_s,
                                     std::vector<int>* part_stage = nullptr, std::vector<bool>* plume_part = nullptr);

// An object's parts at engine time t: a missile with stages, its stages and
// plumes then (above); any other object, shape_parts(body).
std::vector<ShapePart> shape_parts_at(const Object& object, const EngineTime& t);

}  // namespace eoir::universe
