// Astronomical refraction for observers inside the atmosphere (spec
// 4.3.1.1; issue 20 item 6): how much higher a source appears than it is.
// Above 10 deg apparent elevation ERFA's eraRefco model, R = A tan z + B
// tan^3 z of the apparent zenith angle z with A and B from the observer's
// pressure, temperature, humidity and wavelength; below 5 deg Bennett's
// formula (1982, J. Inst. Navigation 35, 255), R = cot(h + 7.31 / (h + 4.4))
// arcmin of the apparent altitude h in degrees, scaled by (P / 1010 hPa)
// (283 K / T); between them a linear blend, so that R is continuous. A ray
// traced through the US76 shells agrees with ERFA's model within 1" from
// 10 deg up, but ERFA's two terms fall 9" short at 6 deg and 22" (4 %) at
// 5 deg, where Bennett's is within 1 % (tests/atmosphere/refraction_test).
#pragma once

namespace eoir::atmosphere {

struct RefractionConstants {
  double a_rad = 0, b_rad = 0;  // eraRefco's A and B
  double bennett_scale = 0;     // (P / 1010 hPa)(283 K / T)
};

// At the observer: pressure (Pa), temperature (K), relative humidity (0-1)
// and wavelength (um). Zero pressure gives no refraction.
RefractionConstants refraction_constants(double pressure_Pa, double temperature_K, double relative_humidity,
                                         double wavelength_um);
// Refraction (rad, >= 0) of a source seen at apparent elevation h.
double refraction_from_apparent_rad(const RefractionConstants& c, double apparent_elevation_rad);
// The same for a source at true elevation e (apparent = e + R, by Newton).
double refraction_from_true_rad(const RefractionConstants& c, double true_elevation_rad);

}  // namespace eoir::atmosphere
