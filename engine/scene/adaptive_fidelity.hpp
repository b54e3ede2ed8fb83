// Adaptive fidelity (DESIGN section 4: "an error budget can choose the
// knobs"): from the world of a frame, built with the sensor's own settings,
// and the sensor's error budget, the cheapest knobs whose estimated error
// stays within it. Each term of the error model bounds one knob's part of
// the relative RMS error of the pixel means, and the terms add in
// quadrature: knobs cheap to tighten (spectral intervals, point-source
// patches) get a tenth of the budget each, the scene grid (samples per pixel
// n, edge sub-samples s and scene mode; cost ~ n^2 + 3 n s^2 per edge pixel,
// smooth about 1.3 times coarse) the rest, at the cheapest setting that fits:
//  - spectral intervals: the error of the band-integral rule (spec 5.3,
//    eq. 48; radiometry/band_integral.hpp) on Planck spectra at the
//    temperatures in the field, computed exactly against the series integral;
//  - samples per pixel and edge sub-samples (spec 4.1.3, 5.2 eqs. 13-14):
//    the coverage error of n x n point samples, each refined to s x s at a
//    silhouette edge, on a pixel crossed by the edge: RMS 1 / (n s sqrt 12)
//    of the contrast (an edge parallel to the sample rows; any other edge
//    does better), summed over the edges a probe of the field finds; and no
//    object imaged extended may turn into a point source (spec 4.1.6.1);
//  - coarse patches of central bodies (spec 4.2.1, 4.1.5.2): a sample takes
//    the radiance of its patch centre, off by |grad L| s / sqrt 12 RMS on a
//    patch of edge s, estimated from the radiance s / 2 away on the surface
//    at probe points; smooth mode (4.2.2) where that is cheaper within the
//    budget;
//  - detailed point sources (spec 4.1.6.1, ERRATA eq. 11): the sum over
//    patches at object_patch_divisions d against 2 d, the smallest d whose
//    change is within the share;
//  - the Earth's atmosphere (issue 20 item 8), a tenth of the budget shared
//    (summed, not in quadrature: their errors can add) by the knobs of its
//    tables that the frame reads: each
//    knob's error at its default as the speed-against-accuracy sweep
//    measured it (tests/bench/results/fidelity_sweep.md, atmosphere scenes),
//    scaled as linear interpolation between nodes, ((n0 - 1) / (n - 1))^2
//    (as the sweep finds them), and the transmittance's sub-sample spacing
//    at the sweep's values (10-80 cm^-1) with its errors there; the
//    coarsest setting within the share.
// Knobs outside the model (PSF reach, point-source tables, FFT padding,
// table sizes) keep the sensor's values.
#pragma once
#include <cstdint>
#include <string>

#include "core/fidelity.hpp"
#include "scene/world.hpp"
#include "universe/universe.hpp"

namespace eoir::scene {

struct FidelityChoice {
  Fidelity fidelity;                     // the knobs the frame is rendered with
  std::int64_t spectral_intervals = 0;   // N of spec 5.3 the frame is rendered with
  double error_budget = 0;               // 0: the sensor's own settings, not chosen
  // The error model's terms (relative RMS of the pixel means).
  double spectral_error = 0, sampling_error = 0, patch_error = 0, point_source_error = 0, atmosphere_error = 0;
  double estimated_error() const;  // their quadrature sum
  // {"error_budget": b, "estimated_error": e, "spectral_intervals": N,
  //  "spectral_error": ..., "sampling_error": ..., "patch_error": ...,
  //  "point_source_error": ..., "atmosphere_error": ..., "<knob>": value, ...} with every fidelity
  //  knob (core/fidelity.hpp).
  std::string json() const;
};

// The sensor's own settings (error budget 0).
FidelityChoice fixed_fidelity(const Fidelity& fidelity, std::int64_t spectral_intervals);

// The cheapest settings within world.fidelity().error_budget (> 0) for the
// frame `world` images; `world` was built with the sensor's own settings and
// spectral_intervals. threads: 0 = all cores.
FidelityChoice choose_fidelity(const World& world, const universe::Universe& universe,
                               std::int64_t spectral_intervals, unsigned threads);

}  // namespace eoir::scene
