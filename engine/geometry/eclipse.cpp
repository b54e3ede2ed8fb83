// Solar-disk occultation (spec 4.1.5.3 culling of eclipsed sources, 6.1.2
// umbra and penumbra). The Sun is a uniform disk (no limb darkening): the
// visible fraction is the unhidden fraction of its solid angle.
//
// Sphere. From the point the Sun is a cap of angular radius alpha about s,
// the occulter a cap of angular radius rho about o, gamma = angle(s, o). The
// classic shadow function (Montenbruck & Gill, Satellite Orbits, 2000, sec.
// 3.4.2; Orekit and GMAT alike) overlaps plane disks of radii alpha and rho
// at separation gamma: its occulter edge has curvature 1/rho where the true
// limb, a small circle, has geodesic curvature cot(rho), so across the Sun
// the limb is misplaced by (1/rho - cot rho) alpha^2 / 2, and it never
// straightens for a point on the surface. Here, in the azimuthal equidistant
// projection about the Sun's centre (distances from that centre exact,
// curvatures and area ratios to O(alpha^2)), the limb's nearest edge sits
// exactly at delta = gamma - rho and the limb is the plane circle of radius
// b = tan(rho) (its curvature there) for rho >> alpha, blending to b = rho
// (its area) for rho <~ alpha: b = rho + (tan rho - rho) rho^2 / (rho^2 +
// alpha^2); b = infinity, the straight horizon, for a point on the surface.
// The disk overlap uses segment heights, stable for b >> alpha. Error in the
// hidden fraction: O(alpha^2), <= 5e-6 at 1 AU against the exact
// spherical-cap integral (tests/geometry/eclipse_test.cpp).
//
// Spheroid (equatorial radius a, polar radius c, polar axis k). The affine
// map M = I + (a/c - 1) k k^T takes the spheroid to the sphere of radius a
// and segments to segments, so a ray to the Sun is blocked iff its image is
// blocked by that sphere: exact, and the sphere above applies in the mapped
// space. Directions map by u -> Mu/|Mu|, linear across the solar disk to
// O(f alpha) (f = a/c - 1, 0.0034 for WGS84), so the Sun's image is an
// ellipse J(disk of radius alpha), J = (I - s's^T) M / |Ms| between tangent
// planes (s' = Ms/|Ms|), of area pi alpha^2 det M / |Ms|^3. It is replaced by
// the disk of that area (radius R), offsets across it rescaled by R over the
// ellipse's half-width h = alpha |J^T n| along the direction n of the
// occulter. This is exact for a straight limb (an affine map of the ellipse
// onto a disk keeps area ratios and a chord's offset over the half-width)
// and for an occulter inside the Sun's disk (an area ratio): the nearest
// edge goes to delta R/h + (R/h - 1) b R^2 / (b^2 + R^2), moving from the
// first case (b >> R) to the second (b << R: centre at (delta + b) R/h).
// Between them the ellipse's anisotropy (<= f) is left over: hidden-fraction
// error <= 0.13 f where the occulter looks as large as the Sun (4e-4 for the
// Earth 1.4 million km away, near the end of its umbra), ~0.002 f where it
// looks 30 times larger (the Earth from GEO: < 1e-5); measured against ray
// casts of a c = 0.9 a spheroid (tests).
//
// Early out: the occulter's bounding sphere against the solid cone from the
// point around the Sun, without trigonometry; most calls end there.
#include "geometry/eclipse.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::geometry {
namespace {

constexpr double kPi = constants::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kInsideTolerance = 1e-9;  // relative depth for "point inside", as shape_contains

// x - sin(x) without cancellation for small x (series to x^9).
double x_minus_sin(double x) {
  if (std::abs(x) < 0.05) {
    const double x2 = x * x;
    return x * x2 / 6.0 * (1.0 - x2 / 20.0 * (1.0 - x2 / 42.0 * (1.0 - x2 / 72.0)));
  }
  return x - std::sin(x);
}

// Area of the part of a disk of radius r beyond a chord at depth h from its
// edge (0 <= h <= 2r): r^2 (theta - sin theta) / 2, theta the chord's central
// angle, from sin(theta / 4) = sqrt(h / 2r) (no acos(1 - eps) loss).
double segment_area(double r, double h) {
  if (!(h > 0.0)) return 0.0;
  if (h >= 2.0 * r) return kPi * r * r;
  const double theta = 4.0 * std::asin(std::sqrt(h / (2.0 * r)));
  return 0.5 * r * r * x_minus_sin(theta);
}

// The Sun as seen from one point.
struct SunView {
  Vec3 point_m;
  Vec3 dir;             // unit, point -> Sun centre
  double distance_m;    // point -> Sun centre
  double sin_alpha, cos_alpha;
};

// What one occulter does to the Sun seen from one point (trivially
// constructible: an array of them costs nothing until filled).
struct Occultation {
  double hidden;  // fraction of the solar disk
  bool inside;    // the point is inside the occulter
  Vec3 dir;       // unit, point -> occulter centre
  double rho_inner_rad, rho_outer_rad;  // caps inscribed in / enclosing its sky outline
};

// Radius of the plane circle standing for a limb of angular radius rho:
// tan(rho) matches the limb's curvature where it passes the Sun (what counts
// for rho >> alpha), rho its area (what counts for rho <~ alpha).
double limb_radius_rad(double rho, double tan_rho, double alpha) {
  const double rho2 = rho * rho, sum2 = rho2 + alpha * alpha;
  if (std::isinf(tan_rho) || !(sum2 > 0.0)) return tan_rho;
  return rho + (tan_rho - rho) * (rho2 / sum2);
}

// Hidden fraction of a disk of radius a by the plane circle of radius b whose
// nearest edge is at signed distance delta from the disk's centre.
double hidden_disk_fraction(double a, double b, double delta) {
  if (!(a > 0.0)) return delta < 0.0 ? 1.0 : 0.0;  // point Sun: the ray to its centre
  return std::clamp(circle_overlap_area_by_edge(a, b, delta) / (kPi * a * a), 0.0, 1.0);
}

// Input checks that cost nothing unless they fail (no message built before).
void check_finite(const Vec3& v, const char* field) {
  if (!v.allFinite()) throw Error(Status::out_of_range, std::string(field) + ": not finite");
}
void check_radius(double r, const char* field) {
  if (!(r >= 0.0) || !std::isfinite(r)) require_non_negative(r, field);
}

Occultation occult(const SunView& sun, const Occulter& occ) {
  Occultation out;
  out.hidden = 0.0;
  out.inside = false;
  const double a = occ.equatorial_radius_m, c = occ.polar_radius_m;
  const double r_max = std::max(a, c);
  if (!(r_max > 0.0)) return out;
  const Vec3 o = occ.centre_m - sun.point_m;
  const double oo = o.squaredNorm();
  const double r_max2 = r_max * r_max;
  if (oo >= r_max2) {
    if (oo >= sun.distance_m * sun.distance_m) return out;  // behind the Sun
    // Bounding sphere against the solid cone {point + t u : t >= 0, angle(u, dir) <= alpha}.
    const double x = o.dot(sun.dir);
    const double y = o.cross(sun.dir).norm();
    const double along_generator = x * sun.cos_alpha + y * sun.sin_alpha;
    if (along_generator <= 0.0) return out;  // nearest cone point is its apex, |o| >= r_max
    if (y * sun.cos_alpha - x * sun.sin_alpha >= r_max) return out;
  }

  const double alpha_rad = std::asin(sun.sin_alpha);  // the Sun's angular radius
  const double d = std::sqrt(oo);
  out.dir = d > 0.0 ? Vec3(o / d) : Vec3(sun.dir);
  const double r_min = std::min(a, c);
  out.rho_inner_rad = d > r_min ? std::asin(r_min / d) : 0.5 * kPi;
  out.rho_outer_rad = d > r_max ? std::asin(r_max / d) : 0.5 * kPi;

  double edge_rad, limb_radius, sun_radius_rad;
  if (a == c) {
    if (d < a * (1.0 - kInsideTolerance)) {
      out.inside = true;
      out.hidden = 1.0;
      return out;
    }
    const double gamma = std::atan2(o.cross(sun.dir).norm(), o.dot(sun.dir));
    const double cos_side = std::sqrt(std::max(0.0, (d - a) * (d + a)));  // d cos(rho)
    const double rho = std::atan2(a, cos_side);
    edge_rad = gamma - rho;
    limb_radius = limb_radius_rad(rho, cos_side > 0.0 ? a / cos_side : kInf, alpha_rad);
    sun_radius_rad = alpha_rad;
  } else {
    // The spheroid mapped to the sphere of radius a.
    const Vec3 k = occ.polar_axis.normalized();
    const double stretch = a / c - 1.0;
    const auto map = [&](const Vec3& v) -> Vec3 { return v + stretch * k.dot(v) * k; };
    const Vec3 o_mapped = map(o);
    const double d_mapped = o_mapped.norm();
    if (d_mapped < a * (1.0 - kInsideTolerance)) {
      out.inside = true;
      out.hidden = 1.0;
      return out;
    }
    const Vec3 s_mapped = map(sun.dir);
    const double s_norm = s_mapped.norm();
    const Vec3 s_unit = s_mapped / s_norm;
    const double x = o_mapped.dot(s_unit);
    const Vec3 perp = o_mapped - x * s_unit;
    const double y = perp.norm();
    const double cos_side = std::sqrt(std::max(0.0, (d_mapped - a) * (d_mapped + a)));
    const double gamma = std::atan2(y, x), rho = std::atan2(a, cos_side);
    // The Sun's image, an ellipse: its area-equivalent radius (the solid-angle
    // Jacobian of u -> Mu/|Mu| is det M / |Mu|^3) and its half-width across
    // the limb, |J^T n| alpha, n toward the occulter's centre.
    sun_radius_rad = alpha_rad * std::sqrt(a / c / (s_norm * s_norm * s_norm));
    limb_radius = limb_radius_rad(rho, cos_side > 0.0 ? a / cos_side : kInf, sun_radius_rad);
    const Vec3 n = y > 1e-12 * d_mapped ? Vec3(perp / y) : Vec3(s_unit.unitOrthogonal());
    const Vec3 mn = map(n);
    const double half_width_rad = alpha_rad * (mn - sun.dir.dot(mn) * sun.dir).norm() / s_norm;
    // Offsets across the Sun rescaled to the area-equivalent disk: the limb's
    // nearest edge for a large occulter (exact against a straight limb), the
    // centre of a small one (exact for an occulter inside the Sun's disk):
    // edge = delta s + (s - 1) b R^2 / (b^2 + R^2), s = R / half-width.
    const double scale = half_width_rad > 0.0 ? sun_radius_rad / half_width_rad : 1.0;
    const double r2 = sun_radius_rad * sun_radius_rad;
    edge_rad = (gamma - rho) * scale + (scale - 1.0) * r2 / (limb_radius + r2 / limb_radius);
  }
  out.hidden = hidden_disk_fraction(sun_radius_rad, limb_radius, edge_rad);
  return out;
}

void check_sun_inputs(const Vec3& point_m, const Vec3& sun_centre_m, double sun_radius_m) {
  check_finite(point_m, "eclipse point_m");
  check_finite(sun_centre_m, "eclipse sun_centre_m");
  check_radius(sun_radius_m, "eclipse sun_radius_m");
}

SunView make_sun_view(const Vec3& point_m, const Vec3& sun_centre_m, double sun_radius_m) {
  check_sun_inputs(point_m, sun_centre_m, sun_radius_m);
  SunView v;
  v.point_m = point_m;
  const Vec3 s = sun_centre_m - point_m;
  v.distance_m = s.norm();
  v.dir = v.distance_m > 0.0 ? Vec3(s / v.distance_m) : Vec3::UnitX();
  v.sin_alpha = v.distance_m > sun_radius_m ? sun_radius_m / v.distance_m : 1.0;
  v.cos_alpha = std::sqrt(std::max(0.0, (1.0 - v.sin_alpha) * (1.0 + v.sin_alpha)));
  return v;
}

void check_occulter(const Occulter& occ) {
  check_finite(occ.centre_m, "eclipse occulter centre_m");
  check_radius(occ.equatorial_radius_m, "eclipse occulter equatorial_radius_m");
  check_radius(occ.polar_radius_m, "eclipse occulter polar_radius_m");
  if (occ.equatorial_radius_m != occ.polar_radius_m) {
    if (!(occ.equatorial_radius_m > 0.0 && occ.polar_radius_m > 0.0))
      throw Error(Status::out_of_range, "eclipse occulter: a spheroid needs both radii > 0");
    check_finite(occ.polar_axis, "eclipse occulter polar_axis");
    if (!(occ.polar_axis.squaredNorm() > 0.0))
      throw Error(Status::out_of_range, "eclipse occulter polar_axis: zero vector");
  }
}

// Sky cap of `inner` (its enclosing cap) inside the inscribed cap of `outer`.
bool nested(const Occultation& inner, const Occultation& outer) {
  const double gamma = std::atan2(inner.dir.cross(outer.dir).norm(), inner.dir.dot(outer.dir));
  return gamma + inner.rho_outer_rad <= outer.rho_inner_rad;
}

}  // namespace

double circle_overlap_area_by_edge(double r1, double r2, double edge_distance) {
  const double a = r1, b = r2;
  const double delta = std::max(edge_distance, -b);  // the separation is >= 0
  if (!(a > 0.0) || !(b > 0.0) || delta >= a) return 0.0;
  if (delta <= -a) return kPi * a * a;  // disk 1 inside disk 2
  if (std::isinf(b)) return segment_area(a, a - delta);
  const double separation = b + delta;
  if (separation + b <= a) return kPi * b * b;  // disk 2 inside disk 1 (annulus)
  // The common chord lies h_b inside disk 2's edge: h_b = x1 - delta with
  // x1 = (d^2 + a^2 - b^2) / 2d, rewritten without cancellation for b >> a.
  const double h_b = (a - delta) * (a + delta) / (2.0 * separation);
  return segment_area(a, a - delta - h_b) + segment_area(b, h_b);
}

double circle_overlap_area(double r1, double r2, double centre_separation) {
  if (!(r1 > 0.0) || !(r2 > 0.0)) return 0.0;
  // Disk 2 as the larger one keeps the edge distance small and accurate.
  if (r1 > r2) std::swap(r1, r2);
  return circle_overlap_area_by_edge(r1, r2, centre_separation - r2);
}

double solar_disk_hidden_fraction(const Vec3& point_m, const Vec3& sun_centre_m, double sun_radius_m,
                                  const Occulter& occulter) {
  const SunView sun = make_sun_view(point_m, sun_centre_m, sun_radius_m);
  check_occulter(occulter);
  if (sun.distance_m <= sun_radius_m) return 0.0;
  return occult(sun, occulter).hidden;
}

double solar_disk_visible_fraction(const Vec3& point_m, const Vec3& sun_centre_m, double sun_radius_m,
                                   const Occulter* occulters, std::size_t count) {
  if (count == 0) {  // nothing to hide it: the inputs checked, no geometry
    check_sun_inputs(point_m, sun_centre_m, sun_radius_m);
    return 1.0;
  }
  const SunView sun = make_sun_view(point_m, sun_centre_m, sun_radius_m);
  if (occulters == nullptr) throw Error(Status::null_argument, "eclipse occulters: null");
  for (std::size_t i = 0; i < count; ++i) check_occulter(occulters[i]);
  if (sun.distance_m <= sun_radius_m) return 1.0;

  constexpr std::size_t kTracked = 32;  // occulters over the Sun checked for nesting
  std::array<Occultation, kTracked> over_sun;
  std::size_t n_over = 0;
  double untracked_hidden = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const Occultation occ = occult(sun, occulters[i]);
    if (occ.hidden >= 1.0) return 0.0;
    if (occ.hidden <= 0.0) continue;
    if (n_over < kTracked)
      over_sun[n_over++] = occ;
    else
      untracked_hidden += occ.hidden;
  }
  double hidden = untracked_hidden;
  for (std::size_t j = 0; j < n_over; ++j) {
    bool dropped = false;
    for (std::size_t i = 0; i < n_over && !dropped; ++i)
      if (i != j && nested(over_sun[j], over_sun[i]))
        dropped = i < j || !nested(over_sun[i], over_sun[j]);  // of two equal caps keep the first
    if (!dropped) hidden += over_sun[j].hidden;
  }
  return std::clamp(1.0 - hidden, 0.0, 1.0);
}

double solar_disk_visible_fraction(const Vec3& point_m, const Vec3& sun_centre_m, double sun_radius_m,
                                   const std::vector<Occulter>& occulters) {
  return solar_disk_visible_fraction(point_m, sun_centre_m, sun_radius_m, occulters.data(), occulters.size());
}

}  // namespace eoir::geometry
