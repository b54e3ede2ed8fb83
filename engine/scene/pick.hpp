// "For Each Pixel Pick" (spec 6.2.1): what one sample of a rendered scene
// sees: the surface (object, patch, range, temperature, latitude/longitude
// on central bodies) or the sky (RA/Dec), with the effective radiance the
// image holds and the spectral radiance vector of the same surface model.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene_generator.hpp"
#include "scene/world.hpp"

namespace eoir::scene {

struct Pick {
  bool hit = false;             // false: the sky
  std::string object;           // "" for the sky
  std::int32_t patch = -1;      // patch dA index on that object
  double range_m = 0;           // to the surface; the sky sphere's radius for the sky
  bool has_geodetic = false;    // central bodies: latitude/longitude valid
  double latitude_deg = 0, longitude_deg = 0;
  double right_ascension_deg = 0, declination_deg = 0;  // J2000 RA/Dec of the sample direction
  double effective_radiance_W_cm2_sr = 0;               // the image's sample (eq. 48)
  double temperature_K = 0;
  std::vector<double> wavelengths_um;                   // the view's sample wavelengths
  std::vector<double> spectral_radiance_W_cm2_sr_um;    // eq. 4 (eq. 9 under the atmosphere) at those wavelengths; the sky's for the sky
  Eq9Terms terms;                                       // the same term by term (its at_sensor is that vector)
};

// Sample (c, r) of the full grid (guard band included), whose effective
// radiance and hit the scene generator gave.
Pick pick_sample(const World& world, double effective_radiance_W_cm2_sr, const SampleHit& hit, std::int64_t c,
                 std::int64_t r);

// J2000 right ascension in [0, 360) and declination of a direction (deg).
void ra_dec_deg(const Vec3& direction, double& ra_deg, double& dec_deg);

}  // namespace eoir::scene
