#include "engine.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "scene/scene_generator.hpp"
#include "sensor/display.hpp"
#include "sensor/image_chain.hpp"
#include "sensor/sensor_properties.hpp"

namespace eoir {

Engine::Engine(const EngineOptions& options) : options_(options), noise_rng_(options.seed) {}

const sensor::StaticMetrics& Engine::static_metrics(const std::string& name) {
  const universe::Object& s = universe_.sensor(name);
  auto it = metric_cache_.find(name);
  if (it != metric_cache_.end() && it->second.revision == s.revision) return *it->second.metrics;
  sensor::check_consistency(s.sensor);
  auto m = std::make_shared<const sensor::StaticMetrics>(sensor::compute_static_metrics(s.sensor));
  metric_cache_[name] = CachedMetrics{s.revision, m};
  return *m;
}

const scene::Frame& Engine::render(const std::string& name) {
  const sensor::StaticMetrics& m = static_metrics(name);
  const universe::Object& s = universe_.sensor(name);
  auto frame = std::make_shared<scene::Frame>();
  scene::generate_scene(universe_, time_, s, m, options_.threads, *frame);
  sensor::render_sensor_image(s.sensor, m, *frame, noise_rng_);
  const auto display_start = std::chrono::steady_clock::now();
  // Display images (spec 4.1.2): the scene view shows the irradiance of each
  // sample of the field of view (L dOmega) with point sources added to the
  // nearest sample; the sensor view shows electrons.
  const scene::SampleGrid& g = frame->grid;
  const std::int64_t w = g.width(), fw = g.pixels_x * scene::SampleGrid::per_pixel;
  const std::int64_t fh = g.pixels_y * scene::SampleGrid::per_pixel, guard = g.guard_samples();
  std::vector<double> irradiance(static_cast<std::size_t>(fw * fh));
  for (std::int64_t r = 0; r < fh; ++r)
    for (std::int64_t c = 0; c < fw; ++c)
      irradiance[static_cast<std::size_t>(r * fw + c)] =
          frame->scene_radiance[static_cast<std::size_t>((r + guard) * w + c + guard)] *
          g.sample_solid_angle_sr(c + guard, r + guard);
  for (const scene::PointSource& ps : frame->point_sources) {
    const std::int64_t c = std::clamp<std::int64_t>(std::lround(ps.column) - guard, 0, fw - 1);
    const std::int64_t r = std::clamp<std::int64_t>(std::lround(ps.row) - guard, 0, fh - 1);
    irradiance[static_cast<std::size_t>(r * fw + c)] += ps.irradiance_W_cm2;
  }
  frame->scene_display = sensor::compress_for_display(irradiance, s.sensor.display_agc, s.sensor.display_gain_step, 1e-6);
  const double full_scale = std::isfinite(m.saturation_electrons) ? m.saturation_electrons : 1e6;
  frame->sensor_display =
      sensor::compress_for_display(frame->sensor_electrons, s.sensor.display_agc, s.sensor.display_gain_step, full_scale);
  frame->timings.display_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - display_start).count();
  // Per-frame truth: the target metrics of every object in the field
  // (central bodies are backgrounds, not targets), frozen with the frame.
  std::vector<std::pair<std::string, metrics::TargetMetrics>> truth;
  for (const scene::FrameObject& o : frame->objects) {
    if (o.central_body) continue;
    metrics::TargetMetrics t = metrics::target_metrics(universe_, time_, s, m, o.name);
    if (t.in_field) truth.emplace_back(o.name, t);
  }
  frames_[name] = frame;
  truth_[name] = std::move(truth);
  return *frame;
}

const scene::Frame& Engine::frame(const std::string& name) const {
  universe_.sensor(name);
  auto it = frames_.find(name);
  if (it == frames_.end())
    throw Error(Status::no_state, "sensor: no frame rendered for '" + name + "' yet; call eoir_render first");
  return *it->second;
}

metrics::ElementValue Engine::provider(const std::string& group, const std::string& element,
                                       const std::string& sensor, const std::string& target) {
  const metrics::GroupSpec& g = metrics::provider_group(group);
  if (g.needs_target) {
    if (target.empty())
      throw Error(Status::null_argument, "target: group '" + group + "' needs a target object");
    return metrics::target_element(target_metrics(sensor, target), element);
  }
  const sensor::StaticMetrics& m = static_metrics(sensor);
  if (!target.empty()) universe_.get(target, "target");  // a named target must exist even if unused
  return metrics::static_element(m, group, element);
}

const metrics::TargetMetrics& Engine::target_metrics(const std::string& sensor, const std::string& target) {
  const auto key = std::make_pair(sensor, target);
  auto it = target_cache_.find(key);
  if (it != target_cache_.end()) return it->second;
  const sensor::StaticMetrics& m = static_metrics(sensor);
  metrics::TargetMetrics t = metrics::target_metrics(universe_, time_, universe_.sensor(sensor), m, target);
  return target_cache_.emplace(key, t).first->second;
}

const std::vector<std::pair<std::string, metrics::TargetMetrics>>& Engine::truth(const std::string& sensor) const {
  frame(sensor);  // throws no_state before the first render
  return truth_.at(sensor);
}

}  // namespace eoir
