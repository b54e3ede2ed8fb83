#include "radiometry/brdf.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "radiometry/disk_photometry.hpp"

namespace eoir::radiometry {

namespace {

constexpr double kPi = constants::pi;
constexpr double kInvPi = 1.0 / constants::pi;

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n, computed once).
template <int N>
struct GaussLegendre {
  std::array<double, N> node{}, weight{};
  GaussLegendre() {
    for (int i = 0; i < (N + 1) / 2; ++i) {
      double x = std::cos(kPi * (i + 0.75) / (N + 0.5));
      double derivative = 0.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= N; ++k) {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        derivative = N * (x * p1 - p0) / (x * x - 1.0);
        const double step = p1 / derivative;
        x -= step;
        if (std::abs(step) < 1e-16) break;
      }
      node[i] = -x;
      node[N - 1 - i] = x;
      weight[i] = weight[N - 1 - i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
  }
};

// e^-700 ~ 1e-304: a lobe this far down contributes nothing.
constexpr double kNegligibleExponent = -700.0;
// A lobe's term below this fraction of the diffuse part is left out of
// value(): a change below rounding (1e-17 relative).
constexpr double kNegligibleLobe = 1e-17;

// Normalization table sizes (intervals in N.L over [0, 1]).
constexpr double kIntervalsPerLobeWidth = 6.0;
constexpr int kMinIntervals = 16;
constexpr int kMaxIntervals = 512;

// Nodes of the cut-ring integral: u = (1 - cos psi) / 2 for Gauss-Legendre
// nodes psi on [0, pi], with weights including du/dpsi = sin(psi) / 2.
constexpr int kLobeNodes = 32;
struct CutRingRule {
  std::array<double, kLobeNodes> u{}, weight{};
  CutRingRule() {
    const GaussLegendre<kLobeNodes> rule;
    for (int k = 0; k < kLobeNodes; ++k) {
      const double psi = 0.5 * kPi * (rule.node[k] + 1.0);
      u[k] = 0.5 * (1.0 - std::cos(psi));
      weight[k] = rule.weight[k] * 0.5 * kPi * 0.5 * std::sin(psi);
    }
  }
};
const CutRingRule& cut_ring_rule() {
  static const CutRingRule rule;
  return rule;
}

// (1 - e^-x) / x for x >= 0, without cancellation (1 at 0).
double one_minus_exp_over_x(double x) { return x == 0.0 ? 1.0 : -std::expm1(-x) / x; }

// (1 - e^-x (1 + x)) / x^2 for x >= 0 (1/2 at 0): series below 0.1.
double one_minus_exp_times_one_plus_x_over_x2(double x) {
  if (x < 0.1) {
    // sum_{n>=2} (-1)^n (n-1) x^(n-2) / n!
    double sum = 0.0, term = 1.0;  // term = (-x)^(n-2) / n!
    for (int n = 2; n <= 12; ++n) {
      term = (n == 2) ? 0.5 : term * (-x) / n;
      sum += (n - 1) * term;
    }
    return sum;
  }
  return (-std::expm1(-x) - x * std::exp(-x)) / (x * x);
}

// -log(1 - y) / y for y in [0, 1) (1 at 0).
double minus_log1m_over_y(double y) { return y == 0.0 ? 1.0 : -std::log1p(-y) / y; }

// Integral over the azimuth phi of max(0, a cos(phi) + b), a >= 0: the
// visible part of the cosine on a ring of the lobe.
double visible_ring_cosine(double a, double b) {
  if (b >= a) return 2.0 * kPi * b;
  if (b <= -a) return 0.0;
  const double half_width = std::acos(std::clamp(-b / a, -1.0, 1.0));
  return 2.0 * (std::sqrt(std::max(0.0, (a - b) * (a + b))) + b * half_width);
}

}  // namespace

// Lobe-centred coordinates: g the angle to the lobe axis, t = 1 - cos g in
// [0, 2] (dw = dt dphi), phi the azimuth about the axis. With the axis at
// theta from the normal (mu = cos theta, s = sin theta), the normal cosine of
// a direction is a cos(phi) + b with a = sin(g) s and b = cos(g) mu, so
//   H = integral_0^2 e^{-kappa t} P(t) dt,  P = visible_ring_cosine(a, b).
// Rings with t < t1 = 1 - s are wholly above the horizon (P = 2 pi b, exact
// integral); rings with t > t2 = 1 + s wholly below (P = 0); in between the
// ring is cut, P has (t - t1)^{3/2} end behaviour and e^{-kappa t} may be a
// needle at t1 (narrow lobe near grazing). There y = 1 - e^{-kappa (t - t1)}
// makes the weight flat (y/kappa resolves the lobe whatever its width), and
// y = U (1 - cos psi) / 2 smooths both ends for Gauss-Legendre in psi.
double cosine_weighted_lobe_integral(double kappa, double cos_axis_normal) {
  if (!(kappa > 0.0)) return kPi;  // flat lobe: integral of cos over the hemisphere
  const double mu = std::clamp(cos_axis_normal, 0.0, 1.0);
  const double sin_axis = std::sqrt((1.0 - mu) * (1.0 + mu));
  const double t1 = 1.0 - sin_axis;
  const double width = 2.0 * sin_axis;  // t2 - t1
  const double t2 = t1 + width;

  // Whole rings: 2 pi mu integral_0^t1 e^{-kappa t} (1 - t) dt.
  const double x1 = kappa * t1;
  const double whole_rings =
      2.0 * kPi * mu * (t1 * one_minus_exp_over_x(x1) - t1 * t1 * one_minus_exp_times_one_plus_x_over_x2(x1));
  if (width <= 0.0) return whole_rings;

  // Cut rings: e^{-kappa t1} (U / kappa) integral_0^1 P(t(u)) du, with
  // U = 1 - e^{-kappa width}, y = u U, t = t1 + (y / kappa) q(y), all written
  // without dividing by a small kappa.
  const double span = width * one_minus_exp_over_x(kappa * width);  // U / kappa
  const double U = -std::expm1(-kappa * width);
  const CutRingRule& rule = cut_ring_rule();
  double sum = 0.0;
  for (int k = 0; k < kLobeNodes; ++k) {
    const double u = rule.u[k];
    const double t = t1 + u * span * minus_log1m_over_y(u * U);
    if (!(t < t2)) continue;  // only where e^{-kappa (t - t1)} < 1e-16
    const double cos_g = 1.0 - t;
    const double sin_g = std::sqrt(std::max(0.0, t * (2.0 - t)));
    sum += rule.weight[k] * visible_ring_cosine(sin_g * sin_axis, cos_g * mu);
  }
  return whole_rings + std::exp(-x1) * span * sum;
}

namespace {

// Table size for a lobe of concentration kappa: near grazing H varies on the
// scale of the lobe width 1/sqrt(kappa) in N.L, and the cubic error goes as
// (interval * sqrt(kappa))^4.
int normalization_intervals(double kappa) {
  return std::clamp(static_cast<int>(std::ceil(kIntervalsPerLobeWidth * std::sqrt(kappa))), kMinIntervals,
                    kMaxIntervals);
}

// Monomial coefficients in t of the cubic through (tau0 + m, value[m]), m = 0..3.
std::array<double, 4> cubic_through(double tau0, const double* value) {
  std::array<double, 4> coefficients{};
  for (int m = 0; m < 4; ++m) {
    std::array<double, 4> basis{1.0, 0.0, 0.0, 0.0};  // prod_{j != m} (t - tau_j)
    double denominator = 1.0;
    int degree = 0;
    for (int j = 0; j < 4; ++j) {
      if (j == m) continue;
      const double root = tau0 + j;
      for (int d = degree + 1; d > 0; --d) basis[d] = basis[d - 1] - root * basis[d];
      basis[0] *= -root;
      ++degree;
      denominator *= static_cast<double>(m - j);
    }
    for (int d = 0; d < 4; ++d) coefficients[d] += value[m] / denominator * basis[d];
  }
  return coefficients;
}

}  // namespace

Brdf::Brdf(const BrdfParameters& parameters) : parameters_(parameters) {
  validate(parameters, "brdf");
  if (parameters.model == universe::BrdfModel::lunar_lommel_seeliger) {
    // N.L value() = 2 f(g) N.L / (pi (N.L + N.V)) < 2 max f / pi.
    lunar_ = true;
    max_projected_value_per_sr_ = 2.0 * lunar_surface_phase_max() * kInvPi;
    return;
  }
  const double directional = 1.0 - parameters.k0;
  double diffuse_fraction = parameters.k0;
  const struct {
    double weight, sharpness;
    bool backscatter;
  } terms[] = {{directional * (1.0 - parameters.k1), parameters.alpha, false},
               {directional * parameters.k1, parameters.beta, true}};
  for (const auto& term : terms) {
    if (term.weight == 0.0) continue;
    if (term.sharpness == 0.0) {  // flat lobe: e^0 / H = 1/pi
      diffuse_fraction += term.weight;
      continue;
    }
    Lobe lobe;
    lobe.weight = term.weight;
    lobe.kappa = kPi * term.sharpness;
    lobe.backscatter = term.backscatter;
    const int intervals = normalization_intervals(lobe.kappa);
    lobe.intervals_per_unit_cos = intervals;
    std::vector<double> H(static_cast<std::size_t>(intervals) + 1);
    for (int j = 0; j <= intervals; ++j)
      H[static_cast<std::size_t>(j)] = cosine_weighted_lobe_integral(lobe.kappa, static_cast<double>(j) / intervals);
    lobe.cubic.resize(static_cast<std::size_t>(intervals));
    for (int i = 0; i < intervals; ++i) {
      const int first = std::clamp(i - 1, 0, intervals - 3);  // 4-point stencil
      lobe.cubic[static_cast<std::size_t>(i)] = cubic_through(first - i, &H[static_cast<std::size_t>(first)]);
    }
    lobes_.push_back(std::move(lobe));
  }
  // All flux diffuse (k0 = 1 or flat lobes): exactly 1/pi, whatever the
  // rounding of the weights.
  diffuse_per_sr_ = lobes_.empty() ? kInvPi : diffuse_fraction * kInvPi;
  // N.L value() <= diffuse + sum over lobes of max N.L weight / H(N.L)
  // (e^(kappa (cos - 1)) <= 1): per interval of H's table, its upper N.L over
  // the least H of its cubic (at the ends and stationary points).
  max_projected_value_per_sr_ = diffuse_per_sr_;
  for (Lobe& lobe : lobes_) {
    double most = 0, least_H = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < lobe.cubic.size(); ++i) {
      const auto& c = lobe.cubic[i];
      const auto at = [&c](double t) { return c[0] + t * (c[1] + t * (c[2] + t * c[3])); };
      double least = std::min(at(0.0), at(1.0));
      // H' = c1 + 2 c2 t + 3 c3 t^2 = 0 inside (0, 1).
      const double a = 3.0 * c[3], b = 2.0 * c[2], d = c[1], disc = b * b - 4.0 * a * d;
      if (a != 0.0 && disc >= 0.0) {
        for (const double t : {(-b + std::sqrt(disc)) / (2.0 * a), (-b - std::sqrt(disc)) / (2.0 * a)})
          if (t > 0.0 && t < 1.0) least = std::min(least, at(t));
      } else if (a == 0.0 && b != 0.0 && -d / b > 0.0 && -d / b < 1.0) {
        least = std::min(least, at(-d / b));
      }
      const double upper_cos = static_cast<double>(i + 1) / lobe.intervals_per_unit_cos;
      most = std::max(most, least > 0.0 ? upper_cos * lobe.weight / least : std::numeric_limits<double>::infinity());
      least_H = std::min(least_H, least);
    }
    max_projected_value_per_sr_ += most;
    // The lobe's term weight e^x / H is below kNegligibleLobe of the diffuse
    // part (and so of value()) wherever x < ln(kNegligibleLobe diffuse H_min
    // / weight): no exp there.
    lobe.negligible_exponent = kNegligibleExponent;
    if (diffuse_per_sr_ > 0.0 && least_H > 0.0 && std::isfinite(least_H))
      lobe.negligible_exponent =
          std::max(kNegligibleExponent, std::log(kNegligibleLobe * diffuse_per_sr_ * least_H / lobe.weight));
  }
}

double Brdf::Lobe::normalization_H(double cos_incidence) const noexcept {
  const double x = std::min(cos_incidence, 1.0) * intervals_per_unit_cos;
  const std::size_t last = cubic.size() - 1;
  const std::size_t i = std::min(static_cast<std::size_t>(x), last);
  const double t = x - static_cast<double>(i);
  const auto& c = cubic[i];
  return c[0] + t * (c[1] + t * (c[2] + t * c[3]));
}

double Brdf::value(double cos_incidence, double cos_exitance, double cos_light_observer) const noexcept {
  if (!(cos_incidence > 0.0 && cos_exitance > 0.0 && std::isfinite(cos_light_observer))) return 0.0;
  if (lunar_)
    return 2.0 * kInvPi * lunar_surface_phase_of_cos(cos_light_observer) /
           (cos_incidence + cos_exitance);
  double brdf_per_sr = diffuse_per_sr_;
  for (const Lobe& lobe : lobes_) {
    // Cosine to the lobe axis: L.V (back to the source) or M.V (mirror).
    const double cos_to_axis =
        lobe.backscatter ? cos_light_observer : 2.0 * cos_incidence * cos_exitance - cos_light_observer;
    const double exponent = lobe.kappa * (std::min(cos_to_axis, 1.0) - 1.0);
    if (exponent < lobe.negligible_exponent) continue;  // (also skips slow subnormal exp())
    brdf_per_sr += lobe.weight * std::exp(exponent) / lobe.normalization_H(cos_incidence);
  }
  return brdf_per_sr;
}

double Brdf::value(const Eigen::Vector3d& to_light, const Eigen::Vector3d& to_observer,
                   const Eigen::Vector3d& normal) const noexcept {
  return value(normal.dot(to_light), normal.dot(to_observer), to_light.dot(to_observer));
}

double Brdf::directional_hemispherical_reflectance(double incidence_rad) const {
  const double cos_incidence = std::cos(incidence_rad);
  if (!(cos_incidence > 0.0)) return 0.0;
  if (lunar_) {  // midpoint rule over the outgoing hemisphere (exitance x azimuth)
    constexpr int kRings = 180, kAzimuths = 360;
    const double sin_incidence = std::sin(incidence_rad);
    double sum = 0;
    for (int i = 0; i < kRings; ++i) {
      const double theta = 0.5 * kPi * (i + 0.5) / kRings, ce = std::cos(theta), se = std::sin(theta);
      for (int j = 0; j < kAzimuths; ++j) {
        const double phi = 2.0 * kPi * (j + 0.5) / kAzimuths;
        const double cos_lv = cos_incidence * ce + sin_incidence * se * std::cos(phi);
        sum += value(cos_incidence, ce, cos_lv) * ce * se;
      }
    }
    return sum * (0.5 * kPi / kRings) * (2.0 * kPi / kAzimuths);
  }
  // Each lobe integrates to H(kappa, N.L) over the hemisphere (quadrature),
  // divided by the interpolated normalization that value() uses.
  double reflectance = diffuse_per_sr_ * kPi;
  for (const Lobe& lobe : lobes_)
    reflectance +=
        lobe.weight * cosine_weighted_lobe_integral(lobe.kappa, cos_incidence) / lobe.normalization_H(cos_incidence);
  return reflectance;
}

}  // namespace eoir::radiometry
