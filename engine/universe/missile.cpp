#include "universe/missile.hpp"

#include <cmath>
#include <initializer_list>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/limits.hpp"
#include "core/value.hpp"
#include "universe/composite.hpp"
#include "universe/json_document.hpp"
#include "universe/object.hpp"
#include "universe/object_bounds.hpp"

namespace eoir::universe {
namespace {
using nlohmann::json;

[[noreturn]] void bad(const std::string& where, const std::string& what) {
  throw Error(Status::out_of_range, where + ": " + what);
}

void check_keys(const json& j, const std::string& at, std::initializer_list<const char*> known, const char* what) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    bool ok = false;
    for (const char* k : known) ok = ok || it.key() == k;
    if (!ok) throw Error(Status::unknown_name, at + "." + it.key() + ": unknown field of " + what);
  }
}

double number(const json& j, const std::string& key, const std::string& at, Range range, const char* unit,
              double fallback) {
  if (!j.contains(key)) return fallback;
  const std::string where = at + "." + key;
  if (!j[key].is_number()) bad(where, "expected a number");
  const double v = j[key].get<double>();
  require_finite(v, where);
  check_range(v, range, where, unit);
  return v;
}

// Half a turn about x: the plume's apex (its +z) along the missile's -z.
const Eigen::Quaterniond plume_orientation(0.0, 1.0, 0.0, 0.0);

}  // namespace

std::vector<MissileStage> parse_missile_stages(const std::string& text, const std::string& field) {
  const json doc = parse_json_document(text, field, Status::out_of_range);
  if (!doc.is_array()) bad(field, "expected an array of stages");
  if (doc.size() > limits::max_missile_stages)
    throw Error(Status::limit_exceeded, field + ": at most " + std::to_string(limits::max_missile_stages) +
                                            " stages per missile, got " + std::to_string(doc.size()));
  const Range length{object_bounds::min_length_m, object_bounds::max_length_m};
  const Range duration{0, 1e9};
  std::vector<MissileStage> stages;
  std::size_t parts = 0;
  for (std::size_t i = 0; i < doc.size(); ++i) {
    const std::string at = field + "[" + std::to_string(i) + "]";
    const json& s = doc[i];
    if (!s.is_object()) bad(at, "expected an object");
    check_keys(s, at,
               {"length_m", "radius_m", "parts", "separation_s", "drawn_after_separation_s", "separation_speed_m_s",
                "plume"},
               "a missile stage");
    MissileStage st;
    if (!s.contains("length_m")) bad(at + ".length_m", "missing");
    if (!s.contains("radius_m")) bad(at + ".radius_m", "missing");
    st.length_m = number(s, "length_m", at, length, "m", 1.0);
    st.radius_m = number(s, "radius_m", at, length, "m", 0.5);
    if (s.contains("parts")) {
      st.parts = parse_composite(s["parts"].dump(), at + ".parts");
    } else {
      ShapePart body;
      body.kind = ShapeKind::cylinder;
      body.dimensions_m = {st.radius_m, st.length_m};
      body.offset_m = Eigen::Vector3d(0, 0, 0.5 * st.length_m);
      st.parts.push_back(body);
    }
    if (s.contains("separation_s")) {
      st.separation_s = number(s, "separation_s", at, Range{0, 1e9, true}, "s", 0);
    } else if (i + 1 < doc.size()) {
      bad(at + ".separation_s", "missing (only the last stage may stay attached for ever)");
    }
    st.drawn_after_separation_s = number(s, "drawn_after_separation_s", at, duration, "s", 0.0);
    st.separation_speed_m_s = number(s, "separation_speed_m_s", at, Range{0, 1e5}, "m/s", 0.0);
    if (s.contains("plume")) {
      const std::string pa = at + ".plume";
      const json& p = s["plume"];
      if (!p.is_object()) bad(pa, "expected an object");
      check_keys(p, pa, {"length_scale", "width_scale", "on_s", "off_s", "temperature_K", "spectrum"}, "a plume");
      PlumeSettings plume;
      plume.length_scale = number(p, "length_scale", pa, Range{1e-3, 1e3}, "", 1.0);
      plume.width_scale = number(p, "width_scale", pa, Range{1e-3, 1e3}, "", 1.0);
      plume.on_s = number(p, "on_s", pa, duration, "s", 0.0);
      plume.off_s = number(p, "off_s", pa, duration, "s", st.separation_s);
      if (!(plume.off_s > plume.on_s)) bad(pa + ".off_s", "must be after on_s");
      if (p.contains("temperature_K"))
        plume.temperature_K = number(p, "temperature_K", pa, Range{0, object_bounds::max_temperature_K}, "K", 0);
      if (p.contains("spectrum")) {
        if (!p["spectrum"].is_string() || p["spectrum"].get<std::string>().empty())
          bad(pa + ".spectrum", "expected the name of a spectrum of the spectrum table");
        plume.spectrum = p["spectrum"].get<std::string>();
      }
      if (!plume.temperature_K && plume.spectrum.empty())
        bad(pa, "give temperature_K (a gray body of emittance 0.99) or spectrum");
      const double r = plume.width_scale * st.radius_m, len = plume.length_scale * st.length_m;
      check_dimensions(ShapeKind::plume, {r, len}, pa + " (width_scale x radius_m, length_scale x length_m)");
      st.plume = plume;
    }
    parts += st.parts.size() + (st.plume ? 1 : 0);
    stages.push_back(std::move(st));
  }
  if (parts > max_composite_parts)
    throw Error(Status::limit_exceeded, field + ": at most " + std::to_string(max_composite_parts) +
                                            " parts per missile (plumes included), got " + std::to_string(parts));
  return stages;
}

std::vector<double> stage_start_times_s(const std::vector<MissileStage>& stages) {
  std::vector<double> start;
  double t0 = 0;
  for (const MissileStage& s : stages) {
    start.push_back(t0);
    t0 += s.separation_s;
  }
  return start;
}

std::vector<ShapePart> missile_parts(const std::vector<MissileStage>& stages, double t, std::vector<int>* part_stage,
                                     std::vector<bool>* plume_part) {
  std::vector<ShapePart> out;
  const bool launched = std::isfinite(t) && t >= 0;
  const std::vector<double> start = stage_start_times_s(stages);
  const std::size_t n = stages.size();
  // The lowest stage still attached (n: none).
  std::size_t lowest = 0;
  if (launched)
    while (lowest < n && !(t < start[lowest] + stages[lowest].separation_s)) ++lowest;
  for (std::size_t k = 0; k < n; ++k) {
    const MissileStage& s = stages[k];
    double z_aft = 0;
    if (k >= lowest) {
      for (std::size_t j = lowest; j < k; ++j) z_aft += stages[j].length_m;
    } else {
      const double since_separation = t - (start[k] + s.separation_s);
      if (!(since_separation < s.drawn_after_separation_s)) continue;
      for (std::size_t j = k; j < lowest; ++j) z_aft -= stages[j].length_m;
      z_aft -= s.separation_speed_m_s * since_separation;
    }
    for (const ShapePart& p : s.parts) {
      ShapePart q = p;
      q.offset_m.z() += z_aft;
      out.push_back(q);
      if (part_stage) part_stage->push_back(static_cast<int>(k));
      if (plume_part) plume_part->push_back(false);
    }
    if (!launched || !s.plume) continue;
    const double own = t - start[k];
    if (!(own >= s.plume->on_s && own < s.plume->off_s)) continue;
    ShapePart plume;
    plume.kind = ShapeKind::plume;
    plume.dimensions_m = {s.plume->width_scale * s.radius_m, s.plume->length_scale * s.length_m};
    plume.offset_m = Eigen::Vector3d(0, 0, z_aft);
    plume.orientation = plume_orientation;
    plume.material = "gray_body";
    plume.reflectance = 1.0 - plume_emittance;
    plume.temperature_K = s.plume->temperature_K.value_or(0.0);
    if (!s.plume->spectrum.empty()) plume.spectrum = s.plume->spectrum;
    out.push_back(plume);
    if (part_stage) part_stage->push_back(static_cast<int>(k));
    if (plume_part) plume_part->push_back(true);
  }
  return out;
}

std::vector<ShapePart> shape_parts_at(const Object& o, const EngineTime& t) {
  if (o.kind != ObjectKind::missile || !o.body.missile_stage_list || o.body.missile_stage_list->empty())
    return shape_parts(o.body);
  // (to the nanosecond: a stage event on a whole second of UTC falls on it)
  const double since = o.body.launch_time ? std::round(t.seconds_since(*o.body.launch_time) * 1e9) / 1e9
                                          : std::numeric_limits<double>::quiet_NaN();
  return missile_parts(*o.body.missile_stage_list, since);
}

}  // namespace eoir::universe
