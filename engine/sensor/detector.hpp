// The optional detector stage after eq. 55 (beyond spec 5; README "Detector
// model"): a sensor as built, in electrons and ADU. Its input is the
// noise-free response r_L + r_E (eqs. 49-50); with the stage on it takes the
// place of eqs. 53-55's Gaussian noise and saturation level:
//   s    = r * g_pix                                 photo-electrons, PRNU g_pix (0 dead)
//   d    = D_pix t_i                                 dark electrons, DSNU and hot pixels in D_pix
//   q    = min(Poisson(s) + Poisson(d), full well)   charge (exact Poisson at any count)
//   e    = q + N(0, read noise)                      electrons read out
//   ADU  = clamp(floor(e / gain + bias + 1/2), 0, 2^bits - 1)
// The fixed pattern g_pix, D_pix comes from detector_pattern_seed alone (the
// same for every frame); the per-frame draws from the engine's seeded
// generator. With noise_enabled off the draws are their means (no Poisson, no
// read noise): q = min(s + d, full well).
#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "universe/sensor_parameters.hpp"

namespace eoir::sensor {

// The detector's fixed pattern, one value per pixel (row-major).
struct DetectorPattern {
  std::vector<double> response;        // g_pix: 1 + PRNU sigma N(0,1), >= 0; 0 for dead pixels
  std::vector<double> dark_current_e_s;  // D_pix: dark current + DSNU sigma N(0,1), >= 0; hot pixels' own
};

// Builds the pattern of `pixels` pixels from p.pattern_seed (its own
// generator: independent of the engine's noise stream).
DetectorPattern build_detector_pattern(const universe::DetectorParameters& p, std::int64_t pixels);

// The largest ADU value, 2^bits - 1.
std::uint32_t adc_max_adu(const universe::DetectorParameters& p);
// The ADU of e electrons read out: clamp(floor(e / gain + bias + 1/2), 0, 2^bits - 1).
std::uint32_t adu_of_electrons(const universe::DetectorParameters& p, double electrons);
// The ADU of a full well (the SATURATE level), at most 2^bits - 1.
std::uint32_t saturation_adu(const universe::DetectorParameters& p);

// The stage: from the mean response `mean_electrons` (eqs. 49-50) over an
// integration of `integration_time_s`, writes `electrons` (e, above) and
// `adu`. Draws from `rng` when `noise` is on.
void apply_detector(const universe::DetectorParameters& p, const DetectorPattern& pattern,
                    const std::vector<double>& mean_electrons, double integration_time_s, bool noise,
                    std::mt19937_64& rng, std::vector<double>& electrons, std::vector<std::uint32_t>& adu);

}  // namespace eoir::sensor
