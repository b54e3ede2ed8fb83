// One rendered frame of a scene-generator/sensor-model pair: the scene
// generator's output (effective-radiance samples and point sources, spec
// 4.1.1), what each sample hit (for picks, spec 6.2.1), and the sensor image
// (spec 5.11).
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/time.hpp"
#include "geometry/scene_geometry.hpp"
#include "scene/patch_radiance.hpp"
#include "scene/sample_grid.hpp"

namespace eoir::scene {

// An object smaller than a scene sample (spec 4.1.6.1), kept apart from the
// sample grid at its exact focal-plane position.
struct PointSource {
  std::int32_t object_id = -1;
  double column = 0, row = 0;         // fractional sample coordinates in the full grid
  double irradiance_W_cm2 = 0;        // band-integrated at the aperture (eq. 52)
};

// How an object's surface temperature varies (spec 4.3.1.3).
struct ThermalField {
  bool subsolar = false;                  // eq. 12; otherwise each part's temperature_K
  double subsolar_K = 0, night_K = 0;
  Eigen::Vector3d sun_body = Eigen::Vector3d::UnitX();  // unit vector toward the Sun, body frame
  // Temperature where the outward surface normal is n (body frame).
  double at(const Eigen::Vector3d& normal_body, double uniform_K) const {
    if (!subsolar) return uniform_K;
    const double c = normal_body.dot(sun_body);
    return c > 0 ? subsolar_K * std::pow(c, 0.25) : night_K;  // T_ss cos^(1/4)(phi)
  }
};

// The surfaces a hit object is made of (one per shape part), for shading and
// picks.
struct FrameObject {
  std::string name;
  bool central_body = false;  // body frame Earth-fixed for the Earth, J2000-aligned for the others
  std::vector<SurfacePoint> parts;
  double equatorial_radius_m = 0, polar_radius_m = 0;  // central bodies: for latitude/longitude
  ThermalField thermal;
  const SurfacePoint& part(std::int32_t i) const { return parts[static_cast<std::size_t>(i < 0 ? 0 : i)]; }
};

// Wall-clock seconds spent in each stage of the last render (DESIGN.md 1).
struct FrameTimings {
  double setup_s = 0;         // snapshot, culling, classification, tessellation
  double ray_casting_s = 0;   // sample directions and Embree casts
  double shading_s = 0;       // per-patch radiance and band integration (eq. 48)
  double convolution_s = 0;   // OTF convolution by FFT and pixel integration (eq. 49)
  double point_sources_s = 0; // energy on detector (eqs. 50-51)
  double noise_s = 0;         // noise and saturation (eqs. 53-55)
  double display_s = 0;       // display compression (4.1.2)
  std::size_t rays = 0;
  double total_s() const {
    return setup_s + ray_casting_s + shading_s + convolution_s + point_sources_s + noise_s + display_s;
  }
};

struct Frame {
  EngineTime time;
  SampleGrid grid;
  SpectralView spectral;
  bool smooth = false;  // scene mode (spec 4.2): smooth, else coarse
  Eigen::Vector3d boresight_j2000 = Eigen::Vector3d::UnitZ();  // sensor +z
  Eigen::Vector3d up_j2000 = Eigen::Vector3d::UnitY();         // sensor +y
  Eigen::Matrix3d body_to_j2000 = Eigen::Matrix3d::Identity();
  std::vector<FrameObject> objects;          // indexed by object_id of hits
  // What each sample of the full grid (incl. guard, row-major) ends on:
  // object_id (-1 the sky) and shape part. Ranges, points and patches are
  // recomputed for picks by casting that one ray again against `placed`.
  struct SampleHit {
    std::int32_t object_id = -1;
    std::int32_t part = -1;
  };
  std::vector<SampleHit> samples;
  std::vector<geometry::PlacedObject> placed;  // the resolved objects the samples were cast against
  std::vector<double> scene_radiance;        // W cm^-2 sr^-1, full grid incl. guard
  std::vector<PointSource> point_sources;    // inside the field of view
  std::vector<double> sensor_mean;           // electrons, pixels (noise-free r_L + r_E)
  std::vector<double> sensor_electrons;      // electrons, pixels (eq. 55)
  std::vector<std::uint8_t> scene_display;   // samples of the field of view
  std::vector<std::uint8_t> sensor_display;  // pixels
  FrameTimings timings;
};

}  // namespace eoir::scene
