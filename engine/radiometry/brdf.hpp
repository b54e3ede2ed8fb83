// Modified Phong BRDF with backscatter, spec 4.1.4.1 eq. 1 (and, for the
// Moon, the lunar Lommel-Seeliger surface of radiometry/disk_photometry.hpp:
// BRDF = 2 f(g) / (pi (N.L + N.V)), f the lunar surface phase function, g the
// angle between L and V; with SRF = A, I/F = A 2 mu0 / (mu0 + mu) f(g)):
//
//   BRDF = ( k0 + (1-k0) ( k1 beta e^{-pi beta (I.O)}
//                          + (1-k1) alpha e^{-pi alpha (O.R)} ) ) / pi,
//   R = N (2 I.N) - I.
//
// Reading (signs). I is the propagation direction of the incoming ray (from
// the source, into the surface), O the propagation direction of the outgoing
// ray (from the surface to the sensor), N the outward normal. In the scene's
// convention of unit vectors pointing away from the surface, L (to_light),
// V (to_observer), N: I = -L, O = V. Then
//   -(I.O) = L.V                      cosine to the source direction, and
//   -(O.R) = V.M, M = 2 N (N.L) - L   cosine to the mirror direction,
// so both exponents are von Mises-Fisher-like lobes e^{kappa (cos - 1)} (up
// to a constant), with concentration kappa = pi alpha around the mirror
// direction (forward, specular lobe) and pi beta around the direction back to
// the source (backscatter, retro-reflection lobe). (Reading I as pointing to
// the source would put both peaks below the surface.)
//
// Normalization. The spec states that eq. 1 "is normalized such that
// reflected flux is conserved. Every arriving photon will be reflected": the
// directional-hemispherical reflectance
//   rho(theta_i) = integral over the outgoing hemisphere of BRDF cos(theta_o) dw
// is exactly 1 at every incidence angle (the spectral reflectance SRF
// multiplies the BRDF outside, eq. 4). The amplitudes alpha/pi and beta/pi of
// eq. 1 are therefore replaced by exact normalizations:
//   BRDF = k0/pi + (1-k0) ( k1 e^{kappa_b (L.V - 1)} / H(kappa_b, N.L)
//                         + (1-k1) e^{kappa_s (M.V - 1)} / H(kappa_s, N.L) ),
// H(kappa, mu) = integral over the hemisphere of e^{kappa (cos g - 1)} cos(theta_o) dw
// for a lobe whose axis makes cos = mu with the normal (both lobe axes are at
// the incidence angle from N, so one function serves both). Near grazing a
// lobe loses part of its mass below the horizon and H drops, so the lobe is
// brightened to keep rho = 1. alpha = 0 (or beta = 0) is a flat lobe, which
// normalizes to the Lambertian 1/pi. H is tabulated per parameter set against
// mu = N.L by quadrature in lobe-centred coordinates (relative error < 1e-6
// against adaptive quadrature, alpha up to 1000, mu 0..1) on ~6 sqrt(kappa)
// intervals (at least 16) and interpolated by piecewise cubics: rho = 1 within
// 3e-5 at every incidence. Limits: the normalization depends on the incidence
// angle only, so the BRDF is not reciprocal (L <-> V); near grazing a narrow
// lobe is brightened (alpha = 100: H(0) is 1/44 of H(1)) because its flux
// leaves at small cos(theta_o); the irradiance factor N.L of eq. 4 keeps the
// reflected radiance finite.
#pragma once
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "universe/material.hpp"

namespace eoir::radiometry {

// The parameters of eq. 1 are a material's (universe/material.hpp), checked
// by universe::validate. The largest accepted lobe sharpness alpha or beta:
// pi * 1000 is a lobe ~1 deg wide (1/sqrt(kappa) rad); the normalization
// tables are sized for it.
using BrdfParameters = universe::BrdfParameters;
using universe::validate;
constexpr double brdf_max_sharpness = universe::BrdfParameters::max_sharpness;

// H(kappa, mu): integral over the hemisphere cos(theta_o) > 0 of
// e^{kappa (cos g - 1)} cos(theta_o) dw, g the angle to a lobe axis at
// cos(theta) = mu from the normal [sr]. kappa >= 0 (0 gives pi); mu is
// clamped to [0, 1]. Quadrature in lobe-centred coordinates (see brdf.cpp).
double cosine_weighted_lobe_integral(double kappa, double cos_axis_normal);

class Brdf {
 public:
  // Validates (field "brdf") and tabulates the lobe normalizations.
  explicit Brdf(const BrdfParameters& parameters);

  // BRDF of eq. 1 [1/sr]. Unit vectors pointing AWAY from the surface:
  // toward the source (spec I = -to_light), toward the sensor (spec
  // O = to_observer), and the outward normal N. 0 when the source or the
  // observer is on or below the horizon (cosine <= 0) and for non-finite
  // input; never NaN or inf for unit vectors.
  double value(const Eigen::Vector3d& to_light, const Eigen::Vector3d& to_observer,
               const Eigen::Vector3d& normal) const noexcept;
  // The same from the three cosines N.L, N.V and L.V.
  double value(double cos_incidence, double cos_exitance, double cos_light_observer) const noexcept;

  // rho(theta_i) = integral over the outgoing hemisphere of
  // value() cos(theta_o) dw (for tests and diagnostics, ~10 us): the diffuse
  // part plus, per lobe, weight * H(kappa, cos theta_i) by quadrature over
  // the tabulated H that value() divides by. 1 up to the interpolation error
  // (< 3e-5) for incidence in [0, pi/2); 0 beyond.
  double directional_hemispherical_reflectance(double incidence_rad) const;

  const BrdfParameters& parameters() const { return parameters_; }
  // True when the BRDF is exactly 1/pi: k0 = 1, or every weighted lobe flat.
  bool lambertian() const { return lobes_.empty() && !lunar_; }
  // At least N.L value() for every geometry (1/sr; what a source's
  // irradiance at normal incidence is multiplied by); 1/pi when lambertian().
  double max_projected_value_per_sr() const { return max_projected_value_per_sr_; }

 private:
  // One directional lobe: weight * e^{kappa (cos - 1)} / H(kappa, N.L), with
  // H as piecewise cubics on a uniform grid in N.L over [0, 1].
  struct Lobe {
    double weight = 0.0;  // (1-k0) k1 or (1-k0) (1-k1)
    double kappa = 0.0;   // pi beta or pi alpha
    bool backscatter = false;
    double intervals_per_unit_cos = 0.0;
    std::vector<std::array<double, 4>> cubic;  // per interval: H = c0 + c1 t + c2 t^2 + c3 t^3
    double negligible_exponent = 0.0;  // kappa (cos - 1) below it: the term left out (set with the lobes)
    double normalization_H(double cos_incidence) const noexcept;
  };

  BrdfParameters parameters_;
  // The lunar Lommel-Seeliger surface (radiometry/disk_photometry.hpp):
  // 2 f(g) / (pi (N.L + N.V)), its SRF the normal albedo.
  bool lunar_ = false;
  double diffuse_per_sr_ = 0.0;  // k0/pi plus flat lobes
  double max_projected_value_per_sr_ = 0.0;
  std::vector<Lobe> lobes_;      // the non-flat lobes with weight > 0
};

}  // namespace eoir::radiometry
