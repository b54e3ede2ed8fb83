// One sensor model resolved from its parameters (spec 5), once per change of
// them: validated in one place (universe::validate), its optics (eqs. 33-39),
// static metrics (Table 1), spectral view (5.3) and the sample grid it asks
// the scene generator to fill (4.1.3, 5.2) with a guard band as wide as its
// PSF reaches.
#pragma once
#include <memory>
#include <mutex>

#include "core/fidelity.hpp"
#include "geometry/sample_grid.hpp"
#include "radiometry/spectral_view.hpp"
#include "sensor/detector.hpp"
#include "sensor/otf.hpp"
#include "sensor/point_source_model.hpp"
#include "sensor/scene_convolution.hpp"
#include "sensor/static_metrics.hpp"
#include "universe/sensor_parameters.hpp"

namespace eoir::sensor {

// The detector's fixed pattern (detector.hpp), built on first use, once.
struct DetectorPatternCache {
  std::once_flag built;
  DetectorPattern pattern;
};

// The point-source model of a sensor, built on first use, once.
struct PointSourceModelCache {
  std::once_flag built;
  PointSourceModel model;
};

struct SensorModel {
  universe::SensorParameters parameters;
  OpticsModel optics;
  StaticMetrics metrics;
  radiometry::SpectralView spectral;
  geometry::SampleGrid grid;
  const Fidelity& fidelity() const { return parameters.fidelity; }
  // Tables of the energy on detector of point sources (point_source_model.hpp),
  // built by the first call (thread-safe; a few tenths of a second), then
  // shared. Copies of a SensorModel share them: they depend only on optics,
  // grid and fidelity, which resolve_sensor sets once (a change of the
  // sensor's properties resolves a new model, Engine::sensor_model).
  const PointSourceModel& point_sources() const;
  std::shared_ptr<PointSourceModelCache> point_source_cache = std::make_shared<PointSourceModelCache>();
  // The detector stage's fixed pattern (detector_model on), built by the
  // first call from the parameters (thread-safe), shared like the above.
  const DetectorPattern& detector_pattern() const;
  std::shared_ptr<DetectorPatternCache> detector_pattern_cache = std::make_shared<DetectorPatternCache>();
  // The scene convolution's transform size, OTF grid and buffer
  // (scene_convolution.hpp), made by the first frame, shared like the above.
  std::shared_ptr<SceneConvolutionCache> scene_convolution = std::make_shared<SceneConvolutionCache>();
};

// Throws eoir::Error naming the field of an invalid parameter.
std::shared_ptr<const SensorModel> resolve_sensor(const universe::SensorParameters& p);

// How far the PSF reaches in the focal plane (cm): k_d lambda F# of
// diffraction tail, k_j sigma f of jitter and k_f delta / F# of defocus blur
// (core/fidelity.hpp PsfReach). The one formula behind the scene's guard band
// and the point-source window.
double psf_reach_cm(const OpticsModel& optics, const PsfReach& reach);

}  // namespace eoir::sensor
