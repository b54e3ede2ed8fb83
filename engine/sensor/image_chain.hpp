// The sensor model's image chain (spec 5.11): the scene generator's
// effective-radiance image is convolved with the system OTF by FFT and
// integrated over pixels (eq. 49), point sources add their energy on
// detector (eqs. 50-51), then noise (eqs. 53-54) and saturation (eq. 55); the
// dark offset is zero (5.11.3). With the sensor's detector_model on, the
// detector stage (detector.hpp) takes the place of eqs. 53-55. Reads nothing of the scene but its output
// (spec 4.1.1).
#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "radiometry/radiance_image.hpp"
#include "sensor/point_source_render.hpp"
#include "sensor/scene_convolution.hpp"
#include "sensor/sensor_model.hpp"

namespace eoir::sensor {

struct SensorImage {
  std::vector<double> mean_electrons;  // pixels, noise-free r_L + r_E (eqs. 49-50)
  std::vector<double> electrons;       // pixels, total response (eq. 55; the detector stage's e when on)
  std::vector<std::uint32_t> adu;      // pixels, the detector stage's ADU; empty with it off
  double convolution_s = 0;            // OTF convolution by FFT and pixel integration (eq. 49)
  double point_sources_s = 0;          // energy on detector (eqs. 50-51)
  double noise_s = 0;                  // noise and saturation (eqs. 53-55) or the detector stage
};

// Draws noise from `rng` (the engine's seeded generator) when noise is on;
// threads (0 = all cores) share the convolution, whose result does not
// depend on them beyond rounding. `storage`: a previous image whose buffers
// the new one reuses (a frame's fresh pages cost more than its FFTs here).
// `scene_rows`: a frame made in strips (pixel_radiance_in_strips), whose
// scene holds its point sources but no samples; its rows come from there.
SensorImage render_sensor_image(const SensorModel& model, const radiometry::RadianceImage& scene,
                                std::mt19937_64& rng, unsigned threads = 0, SensorImage storage = {},
                                const SceneRowSource* scene_rows = nullptr);

// The scene's point sources in pixel coordinates, streaks in pixels, with
// R_peak,E E^ps / ENSQ electrons each (eq. 50).
std::vector<PointSourceSignal> point_source_signals(const SensorModel& model, const radiometry::RadianceImage& scene);

}  // namespace eoir::sensor
