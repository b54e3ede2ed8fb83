#include "engine.hpp"

#include "core/error.hpp"
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

metrics::ElementValue Engine::provider(const std::string& group, const std::string& element,
                                       const std::string& sensor, const std::string& target) {
  for (const auto& g : metrics::static_provider_groups()) {
    if (group != g.name) continue;
    const sensor::StaticMetrics& m = static_metrics(sensor);
    if (!target.empty()) universe_.get(target, "target");  // a named target must exist even if unused
    return metrics::static_element(m, group, element);
  }
  throw Error(Status::unknown_name, "group: unknown data provider group '" + group + "'");
}

}  // namespace eoir
