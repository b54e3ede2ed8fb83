// One rendered frame of a scene-generator/sensor-model pair, kept until the
// next render of that sensor: the world it imaged, the scene generator's
// output (spec 4.1.1) and what each sample hit (for picks, spec 6.2.1), the
// sensor image (spec 5.11), the display images (4.1.2) and the per-frame
// truth, frozen when it was rendered.
#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "metrics/target_metrics.hpp"
#include "scene/adaptive_fidelity.hpp"
#include "scene/astrometric_frame.hpp"
#include "scene/scene_generator.hpp"
#include "scene/world.hpp"
#include "sensor/display.hpp"
#include "sensor/image_chain.hpp"
#include "sensor/sensor_model.hpp"

namespace eoir {

// Wall-clock seconds spent in each stage of a render (DESIGN section 1).
struct FrameTimings {
  double setup_s = 0;          // the world: snapshot, culling, classification, ray caster
  double ray_casting_s = 0;    // sample rays with the per-sample radiance lookup
  double shading_s = 0;        // point sources: placement, occlusion, irradiance
  double convolution_s = 0;    // OTF convolution by FFT and pixel integration (eq. 49)
  double point_sources_s = 0;  // energy on detector (eqs. 50-51)
  double noise_s = 0;          // noise and saturation (eqs. 53-55)
  double display_s = 0;        // display set-up (4.1.2; the images are made on request: Frame::scene_display)
  double truth_s = 0;          // target metrics of the objects in the field
  std::size_t rays = 0;
  double total_s() const {
    return setup_s + ray_casting_s + shading_s + convolution_s + point_sources_s + noise_s + display_s + truth_s;
  }
};

// One entry of the per-frame truth: an object in the field (central bodies
// only where imaged as point sources: resolved ones are backgrounds, not
// targets) or a catalogue star, with its target metrics.
struct TruthEntry {
  enum class Kind { object = 0, star = 1 };
  Kind kind = Kind::object;
  std::string object;  // the object's name or the star's catalogue id
  metrics::TargetMetrics metrics;
  // Directions from the sensor, degrees. Apparent (J2000 = GCRS axes): where
  // the image has it, before refraction (stars, the Moon and planets at
  // their apparent places; other objects at their geometric direction).
  // Astrometric (ICRS; scene/astrometric_frame.hpp): that direction in the
  // star catalogue's frame, as the frame's astrometric WCS gives it, at the
  // middle, the start and the end of the integration. Geometric: the true
  // direction at the frame time (stars: the catalogue place moved by proper
  // motion and parallax; objects: no light time, no aberration).
  double ra_deg = 0, dec_deg = 0;  // apparent
  double astrometric_ra_deg = 0, astrometric_dec_deg = 0;
  double start_astrometric_ra_deg = 0, start_astrometric_dec_deg = 0;
  double end_astrometric_ra_deg = 0, end_astrometric_dec_deg = 0;
  double geometric_ra_deg = 0, geometric_dec_deg = 0;
  double v_mag = 0, b_v_mag = 0;     // stars
  // Pixel coordinates at the start and the end of the integration (a point
  // source's streak; equal to the frame-time position for extended objects).
  double start_x = 0, start_y = 0, end_x = 0, end_y = 0;
  // Topocentric direction (geometric, unrefracted) from a sensor within
  // frames::horizon_max_height_m of the ellipsoid: azimuth from north through
  // east, elevation above the geodetic horizon; 0 with topocentric false
  // for sensors farther out.
  bool topocentric = false;
  double azimuth_deg = 0, elevation_deg = 0;
  // Air along the line of sight in sea-level vertical columns (spec
  // 6.2.5.4: 1 straight up from sea level): to the object, or toward space
  // for a star; 0 while the Earth's atmosphere is off.
  double air_mass = 0;
};

struct Frame {
  std::shared_ptr<const scene::World> world;
  std::shared_ptr<const sensor::SensorModel> sensor_model;
  scene::SceneImage scene;
  // Made in strips (fidelity scene_memory_max_mib): the scene holds its
  // point sources but no samples, and there is no scene display; the scene
  // radiance and picks are made again from the world on request.
  bool scene_in_strips = false;
  // The worlds of its motion sub-steps (scene/motion_substeps.hpp; none
  // with motion_substeps 1), kept to make its strips again.
  std::vector<std::shared_ptr<const scene::World>> substep_worlds;
  sensor::SensorImage sensor;
  // The display images (spec 4.1.2), made on first request (thread-safe):
  // a frame whose displays nobody reads does not pay for them. The scene's
  // (samples of the field of view) is empty for a frame made in strips.
  const std::vector<std::uint8_t>& scene_display() const;
  const std::vector<std::uint8_t>& sensor_display() const;
  // What the render sets them up with; `_storage`: buffers to reuse.
  sensor::DisplayOptions scene_display_options, sensor_display_options;
  unsigned display_threads = 0;
  mutable std::vector<std::uint8_t> scene_display_storage, sensor_display_storage;
  std::vector<TruthEntry> truth;
  FrameTimings timings;
  // The settings the frame was rendered with: the sensor's own, or those its
  // error budget chose (scene/adaptive_fidelity.hpp); world and sensor_model
  // are built with them.
  scene::FidelityChoice fidelity;
  // The astrometric TAN WCS of the sensor pixels (issue 21 item 1) and the
  // sensor's Earth-fixed (ITRS) position at the frame time.
  scene::AstrometricWcs astrometric_wcs;
  Eigen::Vector3d observer_earth_fixed_m = Eigen::Vector3d::Zero();

  const EngineTime& time() const { return world->time; }
  const geometry::SampleGrid& grid() const { return scene.image.grid; }

 private:
  mutable std::once_flag scene_display_made_, sensor_display_made_;
};

}  // namespace eoir
