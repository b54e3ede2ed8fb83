// The engine: one modeled universe, its time, its sensors' cached metrics and
// its noise generator. No terminal I/O, no global state; one engine per host
// thread (calls on one engine must not overlap).
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "core/time.hpp"
#include "metrics/provider_groups.hpp"
#include "scene/frame.hpp"
#include "sensor/static_metrics.hpp"
#include "universe/universe.hpp"

namespace eoir {

struct EngineOptions {
  std::uint32_t threads = 0;  // 0 = all cores
  std::uint64_t seed = 1;
};

class Engine {
 public:
  explicit Engine(const EngineOptions& options = {});

  universe::Universe& universe() { return universe_; }
  const universe::Universe& universe() const { return universe_; }

  const EngineTime& time() const { return time_; }
  void set_time(const EngineTime& t) {
    time_ = t;
    target_cache_.clear();
  }

  const EngineOptions& options() const { return options_; }
  std::mt19937_64& noise_rng() { return noise_rng_; }
  const std::mt19937_64& noise_rng() const { return noise_rng_; }
  void set_noise_rng(const std::mt19937_64& rng) { noise_rng_ = rng; }

  // Static metrics of a sensor, recomputed only after its parameters change.
  // Throws eoir::Error (unknown sensor, inconsistent parameters).
  const sensor::StaticMetrics& static_metrics(const std::string& sensor);

  // One data-provider element at the engine time. `target` may be empty.
  metrics::ElementValue provider(const std::string& group, const std::string& element, const std::string& sensor,
                                 const std::string& target);

  // Renders the frame of `sensor` at the engine time (spec 4 and 5; DESIGN.md
  // section 1 steps 1-7) and keeps it until the next render.
  const scene::Frame& render(const std::string& sensor);
  // The last frame rendered for `sensor`; throws Error(no_state) if none.
  const scene::Frame& frame(const std::string& sensor) const;

  // Sensor-to-target metrics (spec 5.13) of `target` seen by `sensor` at the
  // engine time, cached until the universe or the time changes.
  const metrics::TargetMetrics& target_metrics(const std::string& sensor, const std::string& target);
  // The objects in the field of the last frame of `sensor`, with their
  // target metrics as they were when it was rendered (per-frame truth).
  const std::vector<std::pair<std::string, metrics::TargetMetrics>>& truth(const std::string& sensor) const;

  // A state, property or object changed: drop results that depend on it.
  void note_change() { target_cache_.clear(); }
  // Drop every cached result (after a restore or removal).
  void invalidate_caches() {
    metric_cache_.clear();
    frames_.clear();
    target_cache_.clear();
    truth_.clear();
  }

 private:
  struct CachedMetrics {
    std::uint64_t revision;
    std::shared_ptr<const sensor::StaticMetrics> metrics;
  };
  EngineOptions options_;
  universe::Universe universe_;
  EngineTime time_;
  std::mt19937_64 noise_rng_;
  std::map<std::string, CachedMetrics> metric_cache_;
  std::map<std::string, std::shared_ptr<scene::Frame>> frames_;
  std::map<std::pair<std::string, std::string>, metrics::TargetMetrics> target_cache_;
  // Per-frame truth, computed with each render.
  std::map<std::string, std::vector<std::pair<std::string, metrics::TargetMetrics>>> truth_;
};

}  // namespace eoir
