#include "radiometry/background_light.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "radiometry/planck.hpp"
#include "radiometry/stellar_photometry.hpp"

namespace eoir::radiometry {
namespace {

constexpr double kPi = constants::pi;

double evaluate(const SpectrumFunction& f, double wavelength_um, const char* field) {
  const double value = f(wavelength_um);
  if (!std::isfinite(value)) throw Error(Status::out_of_range, std::string(field) + ": not finite at " +
                                                                   std::to_string(wavelength_um) + " um");
  return value;
}

}  // namespace

void BackgroundLightParameters::validate() const {
  require_positive(zodiacal_visible_anchor_um, "background.zodiacal_visible_anchor_um");
  require_non_negative(zodiacal_visible_radiance_W_m2_sr_um, "background.zodiacal_visible_radiance_W_m2_sr_um");
  require_positive(zodiacal_thermal_anchor_um, "background.zodiacal_thermal_anchor_um");
  require_non_negative(zodiacal_thermal_radiance_W_m2_sr_um, "background.zodiacal_thermal_radiance_W_m2_sr_um");
  if (!(zodiacal_thermal_anchor_um > zodiacal_visible_anchor_um))
    throw Error(Status::out_of_range, "background.zodiacal_thermal_anchor_um: must exceed the visible anchor");
  require_non_negative(zodiacal_scale, "background.zodiacal_scale");
  require_positive(zodiacal_temperature_K, "background.zodiacal_temperature_K");
  require_positive(starlight_temperature_K, "background.starlight_temperature_K");
  require_non_negative(starlight_S10V, "background.starlight_S10V");
  require_non_negative(airglow_total_irradiance_W_cm2, "background.airglow_total_irradiance_W_cm2");
  require_positive(airglow_line_width_um, "background.airglow_line_width_um");
  double sum = 0.0;
  for (std::size_t i = 0; i < airglow_line_um.size(); ++i) {
    require_positive(airglow_line_um[i], "background.airglow_line_um");
    require_non_negative(airglow_line_fraction[i], "background.airglow_line_fraction");
    sum += airglow_line_fraction[i];
  }
  if (std::abs(sum - 1.0) > 1e-9) throw Error(Status::out_of_range, "background.airglow_line_fraction: must sum to 1");
}

BackgroundLight::BackgroundLight(SpectrumFunction solar_irradiance_W_cm2_um, SpectrumFunction reflectance,
                                 BackgroundLightParameters parameters)
    : solar_(std::move(solar_irradiance_W_cm2_um)), reflectance_(std::move(reflectance)), p_(parameters) {
  if (!solar_) throw Error(Status::null_argument, "background.solar_irradiance: missing");
  if (!reflectance_) throw Error(Status::null_argument, "background.reflectance: missing");
  p_.validate();

  // Integrated starlight: pi s B(0.55 um, T) = pi * S10V * (1 S10(V) radiance).
  starlight_sr_ = kPi * p_.starlight_S10V * kS10V_W_cm2_sr_um /
                  planck_radiance(kVReferenceWavelength_um, p_.starlight_temperature_K);

  // Zodiacal light: a S(l) R(l) + b B(l, T) = pi * scale * L_Leinert(l) at both anchors.
  const double l1 = p_.zodiacal_visible_anchor_um, l2 = p_.zodiacal_thermal_anchor_um;
  const double t1 = kPi * p_.zodiacal_scale * p_.zodiacal_visible_radiance_W_m2_sr_um * kW_m2_to_W_cm2;
  const double t2 = kPi * p_.zodiacal_scale * p_.zodiacal_thermal_radiance_W_m2_sr_um * kW_m2_to_W_cm2;
  const double r1 = evaluate(solar_, l1, "background.solar_irradiance") * evaluate(reflectance_, l1, "background.reflectance");
  const double r2 = evaluate(solar_, l2, "background.solar_irradiance") * evaluate(reflectance_, l2, "background.reflectance");
  const double b1 = planck_radiance(l1, p_.zodiacal_temperature_K);
  const double b2 = planck_radiance(l2, p_.zodiacal_temperature_K);
  const double det = r1 * b2 - r2 * b1;
  if (!(std::abs(det) > 0.0) || !std::isfinite(det))
    throw Error(Status::out_of_range, "background.reflectance: the zodiacal anchors cannot be solved (no reflected "
                                      "sunlight at the visible anchor?)");
  reflection_scale_ = (t1 * b2 - t2 * b1) / det;
  thermal_sr_ = (r1 * t2 - r2 * t1) / det;
  if (reflection_scale_ < 0.0 || thermal_sr_ < 0.0)
    throw Error(Status::out_of_range, "background: zodiacal scales came out negative; check the solar spectrum and "
                                      "reflectance inputs");
}

double BackgroundLight::starlight(double wavelength_um) const {
  return starlight_sr_ * planck_radiance(wavelength_um, p_.starlight_temperature_K);
}

double BackgroundLight::zodiacal_reflected(double wavelength_um) const {
  if (reflection_scale_ == 0.0) return 0.0;
  return reflection_scale_ * evaluate(solar_, wavelength_um, "background.solar_irradiance") *
         evaluate(reflectance_, wavelength_um, "background.reflectance");
}

double BackgroundLight::zodiacal_thermal(double wavelength_um) const {
  return thermal_sr_ * planck_radiance(wavelength_um, p_.zodiacal_temperature_K);
}

double BackgroundLight::airglow(double wavelength_um) const {
  double sum = 0.0;
  const double half = 0.5 * p_.airglow_line_width_um;
  for (std::size_t i = 0; i < p_.airglow_line_um.size(); ++i)
    if (std::abs(wavelength_um - p_.airglow_line_um[i]) <= half)
      sum += p_.airglow_line_fraction[i] * p_.airglow_total_irradiance_W_cm2 / p_.airglow_line_width_um;
  return sum;
}

double BackgroundLight::spectral_irradiance(double wavelength_um) const {
  return starlight(wavelength_um) + zodiacal(wavelength_um) + airglow(wavelength_um);
}

double BackgroundLight::sky_radiance(double wavelength_um) const { return spectral_irradiance(wavelength_um) / kPi; }

double BackgroundLight::airglow_band_irradiance(double low_um, double high_um) const {
  double sum = 0.0;
  const double half = 0.5 * p_.airglow_line_width_um;
  for (std::size_t i = 0; i < p_.airglow_line_um.size(); ++i) {
    const double overlap =
        std::min(high_um, p_.airglow_line_um[i] + half) - std::max(low_um, p_.airglow_line_um[i] - half);
    if (overlap > 0.0)
      sum += p_.airglow_line_fraction[i] * p_.airglow_total_irradiance_W_cm2 * overlap / p_.airglow_line_width_um;
  }
  return sum;
}

double BackgroundLight::band_irradiance(double low_um, double high_um) const {
  require_positive(low_um, "band.low_um");
  require_finite(high_um, "band.high_um");
  if (!(high_um >= low_um)) throw Error(Status::out_of_range, "band.high_um: below band.low_um");
  double total = starlight_sr_ * planck_band_radiance(p_.starlight_temperature_K, low_um, high_um) +
                 thermal_sr_ * planck_band_radiance(p_.zodiacal_temperature_K, low_um, high_um) +
                 airglow_band_irradiance(low_um, high_um);
  if (reflection_scale_ > 0.0 && high_um > low_um) {
    static const double xg[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                                 0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
    static const double wg[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                                 0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    constexpr double kMaxPiece_um = 0.01;
    const auto pieces = static_cast<long>(std::ceil((high_um - low_um) / kMaxPiece_um));
    const double h = (high_um - low_um) / static_cast<double>(pieces);
    double sum = 0.0;
    for (long k = 0; k < pieces; ++k) {
      const double mid = low_um + (static_cast<double>(k) + 0.5) * h;
      for (int j = 0; j < 8; ++j) sum += wg[j] * zodiacal_reflected(mid + 0.5 * h * xg[j]);
    }
    total += 0.5 * h * sum;
  }
  return total;
}

std::vector<double> BackgroundLight::interval_mean_irradiances(const SpectralBand& band) const {
  band.validate();
  std::vector<double> out(static_cast<std::size_t>(band.intervals));
  const double dl = band.interval_um();
  for (std::int64_t i = 0; i < band.intervals; ++i) {
    const double lo = band.grid_wavelength_um(i);
    out[static_cast<std::size_t>(i)] = band_irradiance(lo, lo + dl) / dl;
  }
  return out;
}

double diffuse_starlight_S10V(double imaged_v0_stars) {
  require_non_negative(imaged_v0_stars, "background.imaged_v0_stars");
  return std::max(0.0, kAllSkyStarlightV0Stars - imaged_v0_stars) * 1.0e4 / kSkyArea_deg2;
}

}  // namespace eoir::radiometry
