// Stars as blackbody point sources (spec 4.1.6.1): E_lambda = m0 B_lambda(T),
// T the star's effective temperature and m0 [sr] the solid angle that makes
// the star's V magnitude come out right.
//
// Temperature from B-V: Ballesteros (2012), "New insights into black bodies",
// EPL 97, 34008, eq. 14:
//   T = 4600 K [1 / (0.92 (B-V) + 1.7) + 1 / (0.92 (B-V) + 0.62)].
// It treats a star as a blackbody with the colour the Johnson B and V filters
// see; it gives 5778 K at the solar B-V of 0.65 and 10125 K at B-V = 0.
// Validity: B-V in [-0.4, 2.0] (O/B to M stars; the relation is a smooth fit,
// used here only to shape the spectrum). Outside the range the colour is
// clamped to it and the result flagged by b_v_in_range().
//
// Zero point: Bessell, Castelli & Plez (1998), A&A 333, 231, Table A2: a star
// of V = 0 has f_lambda = 363.1e-11 erg cm^-2 s^-1 A^-1
// = 3.631e-12 W cm^-2 um^-1 in V. Two calibrations of m0:
//  - VZeroPoint::monochromatic_0p55um (default): m0 B(0.55 um, T) =
//    3.631e-12 * 10^(-0.4 V) exactly, the convention of spec ERRATA 6.2.5.2;
//  - VZeroPoint::v_passband_mean: the passband mean of m0 B over the
//    Bessell (1990, PASP 102, 1181, Table 2) V response S (energy-weighted,
//    <f> = int f S dl / int S dl, as BCP98 define synthetic magnitudes) equals
//    3.631e-12 * 10^(-0.4 V). For a 10125 K (B-V = 0) star this puts
//    E(0.55 um) 0.6 % below 3.631e-12 (3.611e-12; a blackbody is not Vega); for cool
//    stars it is the better choice because the effective wavelength of V
//    moves redwards.
#pragma once

namespace eoir::radiometry {

// BCP98 V zero point [W cm^-2 um^-1].
constexpr double kVZeroPointIrradiance_W_cm2_um = 3.631e-12;
// Wavelength of the monochromatic calibration [um].
constexpr double kVReferenceWavelength_um = 0.55;
constexpr double kMinBVForTemperature = -0.4;
constexpr double kMaxBVForTemperature = 2.0;

enum class VZeroPoint { monochromatic_0p55um, v_passband_mean };

// Ballesteros (2012) eq. 14 [K]; B-V clamped to [-0.4, 2.0]. Throws
// out_of_range for non-finite input.
double temperature_from_b_v(double b_v_mag);
bool b_v_in_range(double b_v_mag);

// Bessell (1990) V response (normalised to 1 at 530 nm), linear between the
// 10 nm table points, 0 outside 470-700 nm.
double bessell_v_response(double wavelength_um);

// m0 [sr] for a star of magnitude V and temperature T (> 0).
double m0_sr(double v_mag, double temperature_K, VZeroPoint zero_point = VZeroPoint::monochromatic_0p55um);

// E_lambda = m0 B_lambda(T) [W cm^-2 um^-1] with T from B-V.
double stellar_spectral_irradiance(double wavelength_um, double v_mag, double b_v_mag,
                                   VZeroPoint zero_point = VZeroPoint::monochromatic_0p55um);

// int_low^high E_lambda d lambda [W cm^-2], exact (series Planck integral).
double stellar_band_irradiance(double low_um, double high_um, double v_mag, double b_v_mag,
                               VZeroPoint zero_point = VZeroPoint::monochromatic_0p55um);

// Passband mean int E S dl / int S dl over the Bessell V response [W cm^-2 um^-1]
// (a synthetic V measurement: V = -2.5 log10(mean / 3.631e-12)).
double v_passband_mean_irradiance(double v_mag, double b_v_mag, VZeroPoint zero_point);

}  // namespace eoir::radiometry
