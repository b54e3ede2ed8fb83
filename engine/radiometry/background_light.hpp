// Background ("basement") light of spec 4.1.4 and eq. 4: the spectral
// irradiance E_bkg(lambda) [W cm^-2 um^-1] that every surface other than the
// sky receives from the night sky, the sum of
//   - integrated starlight: a scaled 3900 K blackbody,
//   - zodiacal light: the solar spectrum reflected by the Mars surface
//     material (scaled) plus a scaled 250 K blackbody,
//   - airglow: lines at 0.5577, 0.630 and 0.589 um totalling 5.1e-18 W cm^-2
//     (spec 4.1.4; ERRATA: micrometres).
// A surface reflects it as SRF * E_bkg / pi (eq. 4, a hemispherical-
// directional reflectance of 1/pi): E_bkg = pi L_sky for a sky of uniform
// radiance L_sky, so a 100 % Lambertian reflector shows exactly L_sky (the
// quantity spec 6.2.1 compares with Leinert et al.).
//
// Sky radiance where a sample hits no object: sky_radiance() = E_bkg / pi.
// Spec 4.1.4 leaves "the galaxy" (the sky sphere) out of the basement because
// a galactic image was to be painted there; without such an image the sky's
// own diffuse brightness is the radiance a sensor sees against empty sky, and
// E_bkg / pi is by construction that brightness, so the engine uses it.
// Stars drawn as points are not counted twice: with a star field the
// integrated starlight is the whole sky's less the catalogue's stars to the
// field's limit (diffuse_starlight_S10V; issue 21).
//
// Scale factors (all radiances as published, W m^-2 sr^-1 um^-1; the engine
// works in W cm^-2, 1 W m^-2 = 1e-4 W cm^-2):
//  - zodiacal light: Leinert et al. (1998, A&AS 127, 1), Table 19, the
//    zodiacal light spectrum at 90 deg elongation in the ecliptic:
//    2.6e-6 at 0.5 um and 7.5e-7 at 12 um. The reflected and thermal scales
//    are solved so that the sum matches both points exactly. Leinert Table
//    16 gives the same direction as 202 S10 and the ecliptic pole as 60 S10
//    ("60 +- 3 S10", Sect. 8): zodiacal_scale = 60 / 202 moves the model to
//    the pole (applied to both terms).
//  - integrated starlight: V-band surface brightness in S10(V) (one V = 10
//    star per square degree; 1 S10(V) = 1e-4 * 3.631e-12 W cm^-2 um^-1 /
//    3.0462e-4 sr = 1.192e-12 W cm^-2 sr^-1 um^-1 at 0.55 um, the zero point
//    of stellar_photometry). Default 109 S10(V): the whole-sky mean of all
//    starlight, the light of ~450 V = 0 stars spread over 41253 deg^2
//    (Sky & Telescope, "If you combine the magnitudes of all visible
//    stars...": stars to V = 10.5 give 225 V = 0 stars, about half of all
//    starlight; its V < 6.5 sum of 100 agrees with the shipped catalogue's
//    95.8). The sky mean is what illuminates a surface of any orientation;
//    Leinert's integrated-starlight tables were not available to us. The
//    converted catalogue's own sum to V = 10.5 is 219.8 V = 0 stars
//    (tests/sky/background_light_test.cpp checks it against the 225).
//  - airglow: the spec's total, split equally between the three lines (the
//    spec gives no split); each line a boxcar of width airglow_line_width_um
//    (a numerical width, not the physical one) so that a point sample at the
//    line centre returns fraction * total / width and band integrals are
//    exact on any grid (band_irradiance, interval_mean_irradiances).
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "radiometry/band_integral.hpp"
#include "core/tabulated_function.hpp"

namespace eoir::radiometry {

// A spectrum as a function of wavelength [um].
using SpectrumFunction = std::function<double(double wavelength_um)>;
using TabulatedSpectrum = TabulatedFunction;

// Leinert et al. (1998) Table 19: zodiacal light at 90 deg elongation in the
// ecliptic [W m^-2 sr^-1 um^-1].
constexpr std::array<double, 16> kLeinertTable19Wavelength_um = {0.2, 0.3, 0.4, 0.5, 0.7, 0.9, 1.0, 1.2,
                                                                 2.2, 3.5, 4.8, 12., 25., 60., 100., 140.};
constexpr std::array<double, 16> kLeinertTable19Radiance_W_m2_sr_um = {
    2.5e-8, 5.3e-7, 2.2e-6, 2.6e-6, 2.0e-6, 1.3e-6, 1.2e-6, 8.1e-7,
    1.7e-7, 5.2e-8, 1.2e-7, 7.5e-7, 3.2e-7, 1.8e-8, 3.2e-9, 6.9e-10};
// Leinert et al. (1998) Table 16 and Sect. 8 [S10 at 500 nm].
constexpr double kLeinertZodiacal90DegEclipticS10 = 202.0;
constexpr double kLeinertZodiacalEclipticPoleS10 = 60.0;
// 1 S10(V) as a radiance at 0.55 um [W cm^-2 sr^-1 um^-1] (see above).
constexpr double kS10V_W_cm2_sr_um = 1.0e-4 * 3.631e-12 / 3.0461741978670859e-4;
// All starlight of the sky as V = 0 stars (Sky & Telescope, above), and the
// sky's area [deg^2]: 450 1e4 / 41253 = 109 S10(V).
constexpr double kAllSkyStarlightV0Stars = 450.0;
constexpr double kSkyArea_deg2 = 41252.96124941928;
// The integrated starlight left diffuse when stars worth imaged_v0_stars
// V = 0 stars (the catalogue's to the field's limit,
// universe::StarCatalog::v0_equivalent_stars) are drawn as points [S10(V)],
// never below 0.
double diffuse_starlight_S10V(double imaged_v0_stars);
constexpr double kW_m2_to_W_cm2 = 1.0e-4;

struct BackgroundLightParameters {
  // Zodiacal light anchors (Leinert Table 19) and scale.
  double zodiacal_visible_anchor_um = 0.5;
  double zodiacal_visible_radiance_W_m2_sr_um = 2.6e-6;
  double zodiacal_thermal_anchor_um = 12.0;
  double zodiacal_thermal_radiance_W_m2_sr_um = 7.5e-7;
  double zodiacal_scale = 1.0;            // kLeinertZodiacalEclipticPoleS10 / kLeinertZodiacal90DegEclipticS10 for the pole
  double zodiacal_temperature_K = 250.0;  // spec 4.1.4
  // Integrated starlight.
  double starlight_temperature_K = 3900.0;  // spec 4.1.4
  double starlight_S10V = 109.0;  // all of it: kAllSkyStarlightV0Stars 1e4 / kSkyArea_deg2
  // Airglow.
  double airglow_total_irradiance_W_cm2 = 5.1e-18;  // spec 4.1.4
  std::array<double, 3> airglow_line_um = {0.5577, 0.630, 0.589};
  std::array<double, 3> airglow_line_fraction = {1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};
  double airglow_line_width_um = 0.001;
  // Throws eoir::Error(out_of_range) naming the field.
  void validate() const;
};

class BackgroundLight {
 public:
  // solar_irradiance_W_cm2_um: the solar spectral irradiance at 1 au;
  // reflectance: the Mars surface material's spectral reflectance (0..1).
  // Both are sampled only through this object; throws out_of_range if the
  // anchors cannot be solved (e.g. zero reflectance at the visible anchor).
  BackgroundLight(SpectrumFunction solar_irradiance_W_cm2_um, SpectrumFunction reflectance,
                  BackgroundLightParameters parameters = {});

  // Components and sum of E_bkg [W cm^-2 um^-1].
  double starlight(double wavelength_um) const;
  double zodiacal_reflected(double wavelength_um) const;
  double zodiacal_thermal(double wavelength_um) const;
  double zodiacal(double wavelength_um) const { return zodiacal_reflected(wavelength_um) + zodiacal_thermal(wavelength_um); }
  double airglow(double wavelength_um) const;
  double spectral_irradiance(double wavelength_um) const;
  // E_bkg / pi [W cm^-2 sr^-1 um^-1]: the surface term of eq. 4 per unit SRF
  // and the sky radiance.
  double sky_radiance(double wavelength_um) const;

  // int_low^high E_bkg d lambda [W cm^-2]: blackbody terms and lines exact,
  // the reflected term by 8-point Gauss-Legendre on pieces of at most 0.01 um.
  double band_irradiance(double low_um, double high_um) const;
  double airglow_band_irradiance(double low_um, double high_um) const;
  // Mean of E_bkg over each interval of the band [W cm^-2 um^-1]: the
  // spectral vector to use on a coarse grid (lines are never missed).
  std::vector<double> interval_mean_irradiances(const SpectralBand& band) const;

  // The scale factors solved at construction.
  double starlight_solid_angle_sr() const { return starlight_sr_; }        // E = s B(T)
  double zodiacal_reflection_scale() const { return reflection_scale_; }  // E = a E_sun SRF
  double zodiacal_thermal_solid_angle_sr() const { return thermal_sr_; }  // E = b B(T)
  const BackgroundLightParameters& parameters() const { return p_; }

 private:
  SpectrumFunction solar_;
  SpectrumFunction reflectance_;
  BackgroundLightParameters p_;
  double starlight_sr_ = 0.0;
  double reflection_scale_ = 0.0;
  double thermal_sr_ = 0.0;
};

}  // namespace eoir::radiometry
