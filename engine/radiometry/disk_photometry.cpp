#include "radiometry/disk_photometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::radiometry {
namespace {

constexpr double kDeg = constants::pi / 180.0;
// Past this, Allen's lunar law is held (Krisciunas & Schaefer 1991).
constexpr double kLunarLawLimitDeg = 150.0;
// Allen's Delta V(g) = 0.026 g + 4e-9 g^4 (g in deg).
constexpr double kAllenLinearMagPerDeg = 0.026, kAllenQuarticMagPerDeg4 = 4.0e-9;

// 10^(-0.4 m): the brightness ratio of m magnitudes (exp, cheaper than pow,
// within about 1e-15 of it).
double brightness_of_magnitudes(double m) { return std::exp(-0.4 * constants::ln10 * m); }

double poly(double x, std::initializer_list<double> c) {  // c0 + c1 x + c2 x^2 + ...
  double sum = 0, power = 1;
  for (const double k : c) {
    sum += k * power;
    power *= x;
  }
  return sum;
}

double wrap_360(double deg) {
  const double w = std::fmod(deg, 360.0);
  return w < 0 ? w + 360.0 : (w >= 360.0 ? 0.0 : w);
}

// Stirling's interpolation formula (central differences, five nodes: the
// tabulated x0 at or below the angle and two on either side), on a table of
// 36 values every 10 deg around the circle. With p = (x - x0) / 10,
// f = f0 + p mu.delta f0 + p^2/2 delta^2 f0 + p (p^2 - 1)/6 mu.delta^3 f0
//     + p^2 (p^2 - 1)/24 delta^4 f0.
double stirling_on_circle(const double (&table)[36], double deg) {
  const double x = wrap_360(deg) / 10.0;
  const int k = std::min(static_cast<int>(x), 35);
  const double p = x - k;
  double f[5];
  for (int i = 0; i < 5; ++i) f[i] = table[(k - 2 + i + 36) % 36];
  const double d1[4] = {f[1] - f[0], f[2] - f[1], f[3] - f[2], f[4] - f[3]};
  const double d2[3] = {d1[1] - d1[0], d1[2] - d1[1], d1[3] - d1[2]};
  const double d3[2] = {d2[1] - d2[0], d2[2] - d2[1]};
  const double d4 = d3[1] - d3[0];
  return f[2] + p * 0.5 * (d1[1] + d1[2]) + 0.5 * p * p * d2[1] + p * (p * p - 1) / 6.0 * 0.5 * (d3[0] + d3[1]) +
         p * p * (p * p - 1) / 24.0 * d4;
}

}  // namespace

DiskPhaseLaw disk_phase_law(universe::CentralBody body) {
  using universe::CentralBody;
  switch (body) {
    case CentralBody::moon: return DiskPhaseLaw::moon;
    case CentralBody::mercury: return DiskPhaseLaw::mercury;
    case CentralBody::venus: return DiskPhaseLaw::venus;
    case CentralBody::mars: return DiskPhaseLaw::mars;
    case CentralBody::jupiter: return DiskPhaseLaw::jupiter;
    case CentralBody::saturn: return DiskPhaseLaw::saturn;
    case CentralBody::uranus: return DiskPhaseLaw::uranus;
    case CentralBody::neptune: return DiskPhaseLaw::neptune;
    default: return DiskPhaseLaw::lambertian_sphere;
  }
}

double lambertian_sphere_phase(double cos_psi) {
  const double c = std::clamp(cos_psi, -1.0, 1.0);
  return (std::sqrt((1.0 - c) * (1.0 + c)) + (constants::pi - std::acos(c)) * c) / constants::pi;
}

double lommel_seeliger_sphere_phase(double g) {
  g = std::clamp(g, 0.0, constants::pi);
  if (g < 1e-9) return 1.0;
  if (g > constants::pi - 1e-9) return 0.0;
  return std::max(0.0, 1.0 - std::sin(g / 2) * std::tan(g / 2) * std::log(1.0 / std::tan(g / 4)));
}

double lunar_phase_magnitude(double phase_angle_deg) {
  const double g = std::min(std::fabs(phase_angle_deg), kLunarLawLimitDeg);
  return kAllenLinearMagPerDeg * g + kAllenQuarticMagPerDeg4 * g * g * g * g;
}

double lunar_surface_phase(double phase_angle_rad) {
  const double g = std::min(std::clamp(phase_angle_rad, 0.0, constants::pi), kLunarLawLimitDeg * kDeg);
  if (g < 1e-9) return 1.0;
  return brightness_of_magnitudes(lunar_phase_magnitude(g / kDeg)) / lommel_seeliger_sphere_phase(g);
}

namespace {

// A law of the phase angle g on [0, kLunarLawLimitDeg) against t = sin(g / 2)
// = sqrt((1 - cos g) / 2): cubic Hermite between 32,768 nodes, slopes from
// fourth-order differences at an eighth of the spacing (central, one-sided
// at the two ends: the law is read only on [0, limit]; their error adds
// below 1e-15). Within 1e-14 of the law where it is smooth in t
// (disk_photometry_test); a call costs a square root, not an acos, an exp,
// a tan and a log. For the Moon's light on every Earth sample and the
// Moon's own samples.
class HalfAngleTable {
 public:
  static constexpr int kNodes = 32768;
  template <class Law>
  explicit HalfAngleTable(Law&& law)
      : last_t_(std::sin(0.5 * kLunarLawLimitDeg * kDeg)), per_node_(kNodes / last_t_) {
    const double h = last_t_ / kNodes, d = h / 8;
    const auto at_t = [&](double t) { return law(2.0 * std::asin(t)); };
    for (int k = 0; k <= kNodes; ++k) {
      const double t = k == kNodes ? last_t_ : k * h;
      f_[static_cast<std::size_t>(k)] = at_t(t);
      double slope = 0;
      if (k < 2 || k > kNodes - 2) {  // (-25 f0 + 48 f1 - 36 f2 + 16 f3 - 3 f4) / 12, toward the inside
        const double s = k < 2 ? d : -d;
        slope = (-25.0 * at_t(t) + 48.0 * at_t(t + s) - 36.0 * at_t(t + 2 * s) + 16.0 * at_t(t + 3 * s) -
                 3.0 * at_t(t + 4 * s)) /
                (12.0 * s);
      } else {
        slope = (8.0 * (at_t(t + d) - at_t(t - d)) - (at_t(t + 2 * d) - at_t(t - 2 * d))) / (12.0 * d);
      }
      slope_[static_cast<std::size_t>(k)] = slope * h;
    }
  }
  // The law at t in [0, last_t()).
  double at(double t) const {
    const double s = t * per_node_;
    const auto k = std::min(static_cast<std::size_t>(s), static_cast<std::size_t>(kNodes - 1));
    const double u = s - static_cast<double>(k), u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * f_[k] + (u3 - 2 * u2 + u) * slope_[k] + (3 * u2 - 2 * u3) * f_[k + 1] +
           (u3 - u2) * slope_[k + 1];
  }
  double last_t() const { return last_t_; }

 private:
  double last_t_, per_node_;
  std::array<double, kNodes + 1> f_{}, slope_{};  // the law and its slope in t times the node spacing
};

}  // namespace

double lunar_surface_phase_of_cos(double cos_g) {
  // Tabulated where it is smooth in t = sin(g / 2) (g ln g at 0: from t = 1e-3, g = 0.11 deg).
  static const auto table = std::make_unique<HalfAngleTable>([](double g) { return lunar_surface_phase(g); });
  const double t = std::sqrt(std::max(0.0, 0.5 * (1.0 - cos_g)));
  if (t >= 1e-3 && t < table->last_t()) return table->at(t);
  return lunar_surface_phase(std::acos(std::clamp(cos_g, -1.0, 1.0)));
}

double lunar_surface_phase_max() {
  static const double most = [] {
    double m = 0;
    for (int k = 0; k <= 1800; ++k) m = std::max(m, lunar_surface_phase(constants::pi * k / 1800.0));
    return m;
  }();
  return most;
}

double mallama_hilton_upper_limit_deg(DiskPhaseLaw planet) {
  switch (planet) {  // the observed ranges (Mallama & Hilton 2018, Table 2 and their code)
    case DiskPhaseLaw::mercury: return 170.0;
    case DiskPhaseLaw::venus: return 179.0;
    case DiskPhaseLaw::mars: return 120.0;
    case DiskPhaseLaw::jupiter: return 130.0;
    case DiskPhaseLaw::saturn: return 150.0;
    case DiskPhaseLaw::uranus: return 154.0;
    case DiskPhaseLaw::neptune: return 133.14;
    default: throw Error(Status::out_of_range, "disk photometry: not a planet of Mallama & Hilton (2018)");
  }
}

double mallama_hilton_v_1_alpha(DiskPhaseLaw planet, double a) {
  if (!std::isfinite(a) || a < 0 || a > mallama_hilton_upper_limit_deg(planet))
    throw Error(Status::out_of_range, "disk photometry: phase angle outside Mallama & Hilton's range");
  switch (planet) {
    case DiskPhaseLaw::mercury:  // eq. 2
      return poly(a, {-0.613, 6.3280e-02, -1.6336e-03, 3.3644e-05, -3.4265e-07, 1.6893e-09, -3.0334e-12});
    case DiskPhaseLaw::venus:  // eqs. 3 and 4
      return a < 163.7 ? poly(a, {-4.384, -1.044e-03, 3.687e-04, -2.814e-06, 8.938e-09})
                       : poly(a, {236.05828, -2.81914, 8.39034e-03});
    case DiskPhaseLaw::mars:  // eqs. 6 and 7 (L(lambda_e), L(Ls): face_terms_mag)
      return a <= 50.0 ? poly(a, {-1.601, 2.267e-02, -1.302e-04}) : poly(a, {-0.367, -0.02573, 0.0003445});
    case DiskPhaseLaw::jupiter: {  // eqs. 8 and 9
      if (a <= 12.0) return poly(a, {-9.395, -3.7e-04, 6.16e-04});
      return -9.428 - 2.5 * std::log10(poly(a / 180.0, {1.0, -1.507, -0.363, -0.062, 2.809, -1.876}));
    }
    case DiskPhaseLaw::saturn:  // eqs. 11 and 12, the globe alone (the rings: face_terms_mag)
      return a <= 6.5 ? poly(a, {-8.95, -3.7e-04, 6.16e-04}) : poly(a, {-8.94, 2.446e-04, 2.672e-04, -1.506e-06, 4.767e-09});
    case DiskPhaseLaw::uranus:  // eqs. 13 and 14 (the sub-latitude term: face_terms_mag)
      return a <= 3.1 ? -7.110 : poly(a, {-7.110, 6.587e-03, 1.045e-04});
    case DiskPhaseLaw::neptune:  // eqs. 16 (after 2000.0) and 17
      return a <= 1.9 ? -7.00 : poly(a, {-7.00, 7.944e-03, 9.617e-05});
    default: throw Error(Status::out_of_range, "disk photometry: not a planet of Mallama & Hilton (2018)");
  }
}

FaceAngles face_angles(const DiscView& view) {
  FaceAngles a;
  const frames::Vec3 sun = view.to_sun.normalized(), observer = view.to_observer.normalized();
  a.phase_deg = std::acos(std::clamp(sun.dot(observer), -1.0, 1.0)) / kDeg;
  const frames::Vec3 s = view.body_to_j2000.transpose() * sun, o = view.body_to_j2000.transpose() * observer;
  const auto west = [](const frames::Vec3& d) { return wrap_360(-std::atan2(d.y(), d.x()) / kDeg); };
  a.sub_solar_latitude_deg = std::asin(std::clamp(s.z(), -1.0, 1.0)) / kDeg;
  a.sub_observer_latitude_deg = std::asin(std::clamp(o.z(), -1.0, 1.0)) / kDeg;
  a.sub_solar_west_longitude_deg = west(s);
  a.sub_observer_west_longitude_deg = west(o);
  // The body seen from the Sun, in the J2000 ecliptic (obliquity 84381.406",
  // IAU 2006).
  constexpr double eps = 84381.406 / 3600.0 * kDeg;
  const frames::Vec3 h = -sun;
  a.heliocentric_ecliptic_longitude_deg =
      wrap_360(std::atan2(h.y() * std::cos(eps) + h.z() * std::sin(eps), h.x()) / kDeg);
  return a;
}

double mars_effective_central_meridian_deg(double sub_observer_west_deg, double sub_solar_west_deg) {
  double cm = 0.5 * (sub_observer_west_deg + sub_solar_west_deg);
  if (std::fabs(sub_observer_west_deg - sub_solar_west_deg) > 180.0) cm += 180.0;
  return wrap_360(cm);
}

double mars_solar_longitude_deg(double heliocentric_ecliptic_longitude_deg) {
  return wrap_360(heliocentric_ecliptic_longitude_deg - 85.0);
}

double mars_rotational_correction_mag(double effective_central_meridian_deg) {
  return stirling_on_circle(mars_corrections::kRotationMag, effective_central_meridian_deg);
}

double mars_orbital_correction_mag(double solar_longitude_deg) {
  return stirling_on_circle(mars_corrections::kOrbitMag, solar_longitude_deg);
}

double saturn_ring_opening_deg(double sub_solar_latitude_deg, double sub_observer_latitude_deg) {
  const double product = sub_solar_latitude_deg * sub_observer_latitude_deg;
  return product > 0 ? std::sqrt(product) : 0.0;
}

double saturn_with_rings_v_1_alpha(double a, double ring_opening_deg) {  // eq. 10
  const double sin_b = std::sin(ring_opening_deg * kDeg);
  return -8.914 - 1.825 * sin_b + 0.026 * a - 0.378 * sin_b * std::exp(-2.25 * a);
}

double uranus_sub_latitude_mag(double sub_solar_planetographic_deg, double sub_observer_planetographic_deg) {
  return -0.00084 * 0.5 * (std::fabs(sub_solar_planetographic_deg) + std::fabs(sub_observer_planetographic_deg));
}

double face_terms_mag(DiskPhaseLaw law, bool rings, const FaceAngles& f) {
  switch (law) {
    case DiskPhaseLaw::mars:
      return mars_rotational_correction_mag(
                 mars_effective_central_meridian_deg(f.sub_observer_west_longitude_deg, f.sub_solar_west_longitude_deg)) +
             mars_orbital_correction_mag(mars_solar_longitude_deg(f.heliocentric_ecliptic_longitude_deg));
    case DiskPhaseLaw::saturn: {
      if (!rings) return 0.0;
      constexpr double kPhaseLimitDeg = 6.5, kOpeningLimitDeg = 27.0;  // eq. 10's observed range
      const double a = std::min(f.phase_deg, kPhaseLimitDeg);
      const double b = std::min(saturn_ring_opening_deg(f.sub_solar_latitude_deg, f.sub_observer_latitude_deg),
                                kOpeningLimitDeg);
      return saturn_with_rings_v_1_alpha(a, b) - mallama_hilton_v_1_alpha(DiskPhaseLaw::saturn, a);
    }
    case DiskPhaseLaw::uranus: {
      // Planetographic latitude: tan(phi_g) = tan(phi_c) (a / c)^2.
      const universe::CentralBodyInfo& u = universe::central_body_info(universe::CentralBody::uranus);
      const double k = (u.equatorial_radius_m / u.polar_radius_m) * (u.equatorial_radius_m / u.polar_radius_m);
      const auto graphic = [k](double centric_deg) {
        return std::atan2(std::sin(centric_deg * kDeg) * k, std::cos(centric_deg * kDeg)) / kDeg;
      };
      return uranus_sub_latitude_mag(graphic(f.sub_solar_latitude_deg), graphic(f.sub_observer_latitude_deg));
    }
    default: return 0.0;
  }
}

bool DiskPhotometry::has_face_terms() const {
  return law_ == DiskPhaseLaw::mars || law_ == DiskPhaseLaw::uranus || rings_;
}

double DiskPhotometry::phase(const DiscView& view) const {
  const double cos_psi = view.to_sun.dot(view.to_observer);  // (unit vectors)
  if (!has_face_terms()) return phase(cos_psi);
  return phase(cos_psi) * brightness_of_magnitudes(face_terms_mag(law_, rings_, face_angles(view)));
}

double DiskPhotometry::geometric_albedo_per_srf() const { return law_ == DiskPhaseLaw::moon ? 1.0 : 2.0 / 3.0; }

double DiskPhotometry::phase(double cos_psi) const {
  if (law_ == DiskPhaseLaw::lambertian_sphere) return lambertian_sphere_phase(cos_psi);
  if (law_ == DiskPhaseLaw::moon) {  // Allen's law tabulated from psi = 1e-9 rad to its limit
    static const auto table = std::make_unique<HalfAngleTable>(
        [](double g) { return brightness_of_magnitudes(lunar_phase_magnitude(g / kDeg)); });
    const double t = std::sqrt(std::max(0.0, 0.5 * (1.0 - cos_psi)));
    if (t >= 0.5e-9 && t < table->last_t()) return table->at(t);
  }
  const double psi = std::acos(std::clamp(cos_psi, -1.0, 1.0));
  if (law_ == DiskPhaseLaw::moon) {
    // Phi_LS(psi) f(psi) = 10^(-0.4 Delta V(psi)) up to Allen's limit (f is
    // that over Phi_LS): the same value to rounding, without the two Phi_LS.
    if (psi >= 1e-9 && psi <= kLunarLawLimitDeg * kDeg)
      return brightness_of_magnitudes(lunar_phase_magnitude(psi / kDeg));
    // Past the limit the surface factor is its value there (the same bits, made once).
    static const double surface_at_limit = lunar_surface_phase(kLunarLawLimitDeg * kDeg);
    return lommel_seeliger_sphere_phase(psi) * (psi < 1e-9 ? lunar_surface_phase(psi) : surface_at_limit);
  }
  const double limit_deg = mallama_hilton_upper_limit_deg(law_);
  const double v0 = mallama_hilton_v_1_alpha(law_, 0.0);
  const double a = std::min(psi / kDeg, limit_deg);
  const double in_range = brightness_of_magnitudes(mallama_hilton_v_1_alpha(law_, a) - v0);
  if (psi / kDeg <= limit_deg) return in_range;
  // Past the observed range: a Lambertian sphere's fall from the last angle.
  const double at_limit = lambertian_sphere_phase(std::cos(limit_deg * kDeg));
  return at_limit > 0 ? in_range * lambertian_sphere_phase(cos_psi) / at_limit : 0.0;
}

}  // namespace eoir::radiometry
