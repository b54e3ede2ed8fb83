// Detector footprint MTF (spec 5.12.1, eqs. 56-57). Report-only: the image
// chain integrates the PSF over the pixel instead (eq. 51).
#pragma once

namespace eoir::sensor {

// |sin(pi xi' p) / (pi xi' p)|, xi' in cycles/cm in the focal plane, p in cm
// (eq. 56 horizontal, eq. 57 vertical).
double detector_footprint_mtf(double frequency_cycles_per_cm, double pitch_cm);

// The same against object-space frequency: xi' = xi 1000 / f, xi in cycles/mrad.
double detector_footprint_mtf_object(double frequency_cycles_per_mrad, double pitch_cm, double focal_length_cm);

}  // namespace eoir::sensor
