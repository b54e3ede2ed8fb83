// The engine: one modeled universe, its time, its sensors' resolved models
// and worlds, its frames and its noise generator. It owns its state: every
// change goes through a method here that drops what depends on it. No
// terminal I/O, no global state. Not thread-safe: one caller at a time (the
// C ABI serializes the calls on one handle); two engines are independent.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/time.hpp"
#include "core/value.hpp"
#include "frame.hpp"
#include "metrics/provider_groups.hpp"
#include "scene/pick.hpp"
#include "universe/library.hpp"
#include "universe/universe.hpp"

namespace eoir {

struct EngineOptions {
  std::uint32_t threads = 0;  // 0 = all cores
  std::uint64_t seed = 1;
  std::string data_dir;       // the data folder; "" = core/data_dir.hpp's search
  // Called between the stages of long work with its completed fraction in
  // [0, 1]; returning false cancels it (Error(Status::cancelled)). May be empty.
  std::function<bool(double fraction, const std::string& what)> progress;
  // level 0 debug, 1 info, 2 warning, 3 error. May be empty.
  std::function<void(int level, const std::string& message)> log;
};

class Engine {
 public:
  explicit Engine(const EngineOptions& options = {});

  // ---- state (read-only views; change it through the methods below)
  const universe::Universe& universe() const { return universe_; }
  const EngineTime& time() const { return time_; }
  const EngineOptions& options() const { return options_; }
  const std::mt19937_64& noise_rng() const { return noise_rng_; }

  // ---- changes: each invalidates what depends on it
  void set_time(const EngineTime& t);
  // The object limits (universe/object_limits.hpp); throws naming the field.
  void set_limits(const universe::ObjectLimits& limits);
  void add_object(universe::ObjectKind kind, const std::string& name);
  void add_sensor(const std::string& name, const std::string& parent);
  // Removes an object and the sensors attached to it (never the Sun).
  void remove_object(const std::string& name);
  // frame: 0 J2000, 1 Earth-fixed, 2 geodetic, 3 geodetic with local
  // north-east-down axes (universe/object_motion.hpp).
  void push_state(const std::string& name, const EngineTime& epoch, int frame, const double position[3],
                  const double velocity[3], const double attitude_wxyz[4],
                  const double angular_velocity_rad_s[3] = nullptr);
  // A saved state restored exactly (validated as push_state validates).
  void restore_state(const std::string& name, const universe::PushedState& state);
  void set_property(const std::string& object, const std::string& property, const Value& value);
  void set_sensor_parameters(const std::string& sensor, const universe::SensorParameters& parameters);
  // The user's materials and tabulated spectra (added to or replacing the
  // data folder's; saved with the state).
  void add_material(const universe::Material& material);
  void add_spectrum(const universe::NamedSpectrum& spectrum);
  const std::vector<universe::Material>& user_materials() const { return user_materials_; }
  const std::vector<universe::NamedSpectrum>& user_spectra() const { return user_spectra_; }
  // The materials and spectra (loaded from the data folder on first use;
  // throws io naming the folder if it is missing).
  const universe::Library& library();
  void set_noise_rng(const std::mt19937_64& rng) { noise_rng_ = rng; }

  // ---- derived results, cached until what they depend on changes
  // The sensor's resolved model (validated); throws naming the field.
  std::shared_ptr<const sensor::SensorModel> sensor_model(const std::string& sensor);
  const sensor::StaticMetrics& static_metrics(const std::string& sensor) { return sensor_model(sensor)->metrics; }
  // The world of `sensor` at the engine time: built once per (universe, time).
  std::shared_ptr<const scene::World> world(const std::string& sensor);
  // One data-provider element at the engine time. `target` may be empty.
  metrics::ElementValue provider(const std::string& group, const std::string& element, const std::string& sensor,
                                 const std::string& target);
  // A scalar element at each of `times` (the engine time is left at the last).
  std::vector<double> provider_series(const std::string& group, const std::string& element, const std::string& sensor,
                                      const std::string& target, const std::vector<EngineTime>& times);
  // Sensor-to-target metrics (spec 5.13) at the engine time.
  const metrics::TargetMetrics& target_metrics(const std::string& sensor, const std::string& target);

  // Renders the frame of `sensor` at the engine time (spec 4 and 5; DESIGN
  // section 1 steps 1-7) and keeps it until the next render. On cancellation
  // the previous frame stays.
  const Frame& render(const std::string& sensor);
  // The last frame rendered for `sensor`; throws Error(no_state) if none.
  const Frame& frame(const std::string& sensor) const;
  // Its per-frame truth: the objects in the field with their target metrics.
  const std::vector<TruthEntry>& truth(const std::string& sensor) const { return frame(sensor).truth; }
  // What sample (space 0) or the centre sample of pixel (space 1) (x, y) of
  // the last frame sees.
  scene::Pick pick(const std::string& sensor, int space, std::int64_t x, std::int64_t y) const;
  // The last frame's effective radiance of the field's samples (row-major,
  // field_width x field_height) into values; a frame made in strips has it
  // made again from its world, strip by strip.
  void scene_field_radiance(const std::string& sensor, double* values) const;

  // Worlds built so far (the same world serves a render's image, truth and
  // target metrics).
  std::uint64_t world_builds() const { return world_builds_; }

 private:
  void changed();  // the universe changed: drop every derived result but frames
  // Reports progress; throws Error(cancelled) if the host asks to stop.
  void progress(double fraction, const char* what) const;

  struct CachedWorld {
    std::uint64_t revision = 0;
    EngineTime time;
    std::shared_ptr<const scene::World> world;
  };
  struct CachedModel {
    std::uint64_t revision = 0;
    std::shared_ptr<const sensor::SensorModel> model;
  };
  // Adaptive fidelity: the model and world of the settings chosen for a frame,
  // kept while the choice repeats (point-source tables, FFT plans and
  // tessellations are then not rebuilt).
  struct CachedAdaptive {
    std::uint64_t model_revision = 0, world_revision = 0;
    std::string settings;  // FidelityChoice::json() without the error estimate
    EngineTime time;
    std::shared_ptr<const sensor::SensorModel> model;
    std::shared_ptr<const scene::World> world;
    // The choice made on the sensor's own world `chosen_for`: a function of
    // that world alone, so rendering the same world again reuses it.
    std::shared_ptr<const scene::World> chosen_for;
    scene::FidelityChoice choice;
  };
  // The model and world of `choice` for `sensor` at the engine time.
  void adaptive_frame(const std::string& sensor, const scene::FidelityChoice& choice, Frame& frame);
  EngineOptions options_;
  universe::Universe universe_;
  EngineTime time_;
  std::mt19937_64 noise_rng_;
  std::uint64_t revision_ = 0;  // bumped by every change of the universe
  std::uint64_t world_builds_ = 0;
  std::map<std::string, CachedModel> models_;
  std::map<std::string, CachedWorld> worlds_;
  std::map<std::string, CachedAdaptive> adaptive_;
  std::map<std::pair<std::string, std::string>, metrics::TargetMetrics> target_cache_;  // at revision_ and time_
  std::map<std::string, std::shared_ptr<const Frame>> frames_;
  // Per sensor, the sample and display buffers of the frame the last render
  // replaced (when nothing else held it), reused by the next render: a
  // steady sequence of frames touches no fresh memory.
  struct FrameBuffers {
    scene::SceneImage scene;
    sensor::SensorImage sensor;
    std::vector<std::uint8_t> scene_display, sensor_display;
  };
  std::map<std::string, FrameBuffers> spare_buffers_;
  std::shared_ptr<universe::Library> library_;  // loaded on first use
  std::vector<universe::Material> user_materials_;
  std::vector<universe::NamedSpectrum> user_spectra_;
  std::string last_sky_warning_;  // logged once, not every frame
  std::unique_ptr<scene::WorldCache> world_cache_ = std::make_unique<scene::WorldCache>();  // shared by the worlds
};

}  // namespace eoir
