// The sensor model's image chain (spec 5.11): the effective-radiance image is
// convolved with the system OTF by FFT and integrated over pixels (eq. 49),
// point sources add their energy on detector (eqs. 50-51), then noise (eqs.
// 53-54) and saturation (eq. 55); the dark offset is zero (5.11.3).
#pragma once
#include <random>

#include "scene/frame.hpp"
#include "sensor/static_metrics.hpp"

namespace eoir::sensor {

// Fills frame.sensor_mean and frame.sensor_electrons from frame.scene_radiance
// and frame.point_sources. Draws noise from `rng` (the engine's seeded
// generator) when p.noise_enabled.
void render_sensor_image(const SensorParameters& p, const StaticMetrics& m, scene::Frame& frame,
                         std::mt19937_64& rng);

// Eq. 49 without the responsivity: the scene convolved with the system PSF
// and averaged over each pixel's 4x4 samples (W cm^-2 sr^-1 per pixel).
std::vector<double> pixel_radiance(const SensorParameters& p, const scene::Frame& frame);

}  // namespace eoir::sensor
