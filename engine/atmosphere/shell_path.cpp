#include "atmosphere/shell_path.hpp"

#include <algorithm>
#include <cmath>

namespace eoir::atmosphere {
namespace {

// The map to the space where the ellipsoid is a sphere of radius a.
struct Stretch {
  Vec3 pole;
  double extra;  // a / b - 1
  explicit Stretch(const EarthFigure& e)
      : pole(e.pole), extra(e.equatorial_radius_m / e.polar_radius_m - 1.0) {}
  Vec3 operator()(const Vec3& v) const { return v + extra * v.dot(pole) * pole; }
};

// Altitude above the ellipsoid of a stretched point at radius r whose
// polar component is zp: r - a there is the altitude times 1 + (a/b - 1)
// cos^2(colatitude) to first order in the flattening.
double corrected_altitude(double r, double zp, double a, double extra) {
  const double c = r > 0 ? zp / r : 0.0;
  return (r - a) / (1.0 + extra * c * c);
}

constexpr double kGaussNodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
constexpr double kGaussWeights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};

// Adds w x (what a node of a quadrature holds) to a segment; air_T and
// air_p gather the air-weighted temperature and pressure.
void add_node(const Densities& n, double w, PathSegment& seg, double& air_T, double& air_p) {
  seg.air_m2 += w * n.air_m3;
  seg.h2o_m2 += w * n.h2o_m3;
  seg.o3_m2 += w * n.o3_m3;
  seg.aerosol_tau_550 += w * n.aerosol_550_per_m;
  seg.boundary_aerosol_tau_550 += w * n.boundary_aerosol_550_per_m;
  for (std::size_t g = 0; g < kMixedGases; ++g) seg.mixed_m2[g] += w * n.mixed_m3[g];
  air_T += w * n.air_m3 * n.temperature_K;
  air_p += w * n.air_m3 * n.pressure_Pa;
}

// Closes a segment (its Curtis-Godson temperature and pressure) and adds it
// to the path.
void add_segment(PathSegment& seg, double air_T, double air_p, bool keep, PathColumns& out) {
  if (seg.air_m2 > 0) {
    seg.temperature_K = air_T / seg.air_m2;
    seg.pressure_Pa = air_p / seg.air_m2;
  }
  append_segment(out, seg);
  if (!keep) out.segments.pop_back();
}

// Integrates the line x(t) = p + t d (caller's frame, d of any length) for
// t in [t0, t1]; true length per unit t: |d|.
PathColumns integrate(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& p, const Vec3& d,
                      double t0, double t1, bool keep) {
  PathColumns out;
  const Stretch stretch(earth);
  const double a = earth.equatorial_radius_m;
  const Vec3 ps = stretch(p - earth.centre_m), ds = stretch(d);
  const double A = ds.squaredNorm(), B = 2.0 * ps.dot(ds), C = ps.squaredNorm();
  const double r_top = a + profile.top_altitude_m();
  if (!(A > 0)) return out;
  const double t_near = std::clamp(-B / (2.0 * A), t0, t1);
  const auto r2 = [&](double t) { return (A * t + B) * t + C; };
  const double lowest_r2 = r2(t_near);
  if (!(lowest_r2 < r_top * r_top)) return out;  // above the atmosphere throughout
  // Clip to the top sphere.
  {
    const double disc = B * B - 4.0 * A * (C - r_top * r_top);
    const double s = std::sqrt(std::max(0.0, disc));
    t0 = std::max(t0, (-B - s) / (2.0 * A));
    t1 = std::min(t1, (-B + s) / (2.0 * A));
  }
  if (!(t1 > t0)) return out;
  out.crosses = true;
  // Crossings of every level sphere, and the point nearest the centre.
  std::vector<double> cuts{t0, t1};
  if (t_near > t0 && t_near < t1) cuts.push_back(t_near);
  for (const ProfileLevel& l : profile.levels()) {
    const double r = a + l.altitude_m;
    const double disc = B * B - 4.0 * A * (C - r * r);
    if (disc <= 0) continue;
    const double s = std::sqrt(disc);
    for (const double t : {(-B - s) / (2.0 * A), (-B + s) / (2.0 * A)})
      if (t > t0 && t < t1) cuts.push_back(t);
  }
  std::sort(cuts.begin(), cuts.end());
  const double speed = d.norm();
  out.lowest_altitude_m = corrected_altitude(std::sqrt(std::max(0.0, r2(std::clamp(t_near, t0, t1)))),
                                             (ps + std::clamp(t_near, t0, t1) * ds).dot(earth.pole), a, stretch.extra);
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double ta = cuts[i], tb = cuts[i + 1];
    if (!(tb > ta)) continue;
    const double half = 0.5 * (tb - ta), mid = 0.5 * (ta + tb);
    PathSegment seg;
    double air_T = 0, air_p = 0;
    for (int g = 0; g < 4; ++g) {
      const double t = mid + half * kGaussNodes[g];
      const Vec3 x = ps + t * ds;
      const double r = x.norm();
      const Densities n = profile.at(corrected_altitude(r, x.dot(earth.pole), a, stretch.extra));
      add_node(n, kGaussWeights[g] * half * speed, seg, air_T, air_p);
    }
    seg.length_m = (tb - ta) * speed;
    const Vec3 xm = ps + mid * ds;
    seg.mid_distance_m = mid * speed;
    seg.mid_altitude_m = corrected_altitude(xm.norm(), xm.dot(earth.pole), a, stretch.extra);
    seg.layer = profile.layer_of(seg.mid_altitude_m);
    add_segment(seg, air_T, air_p, keep, out);
  }
  return out;
}
}  // namespace

PathColumns path_between(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                         const Vec3& to_m, bool keep_segments) {
  return integrate(profile, earth, from_m, to_m - from_m, 0.0, 1.0, keep_segments);
}

PathColumns path_to_space(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                          const Vec3& direction, bool keep_segments) {
  // Far enough to leave the top sphere from anywhere inside it.
  const double reach = (from_m - earth.centre_m).norm() + 2.0 * (earth.equatorial_radius_m * 1.01 + profile.top_altitude_m());
  return integrate(profile, earth, from_m, direction.normalized(), 0.0, reach, keep_segments);
}

void append_segment(PathColumns& path, const PathSegment& s) {
  path.length_m += s.length_m;
  path.air_m2 += s.air_m2;
  path.h2o_m2 += s.h2o_m2;
  path.o3_m2 += s.o3_m2;
  path.aerosol_tau_550 += s.aerosol_tau_550;
  path.boundary_aerosol_tau_550 += s.boundary_aerosol_tau_550;
  path.segments.push_back(s);
}

double refractivity(double air_m3) { return 2.926e-4 * air_m3 / kLoschmidt_m3; }

PathColumns refracted_path_to_space(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                                    const Vec3& apparent_direction, bool& ends_on_ground, bool keep) {
  ends_on_ground = false;
  const Stretch stretch(earth);
  const double a = earth.equatorial_radius_m, top = a + profile.top_altitude_m();
  const Vec3 u = apparent_direction.normalized();
  const Vec3 x0 = stretch(from_m - earth.centre_m), d0 = stretch(u).normalized();
  // A start below the surface (a site on the sea floor) is taken at it.
  const double r0 = std::max(x0.norm(), a);
  if (!(r0 < top)) return path_to_space(profile, earth, from_m, u, keep);
  const double length_scale = 1.0 / stretch(u).norm();  // true length per stretched length, near the start
  const double pole_cos = x0.norm() > 0 ? x0.dot(earth.pole) / x0.norm() : 0.0;  // the shells' altitude correction
  const auto h_of = [&](double r) { return (r - a) / (1.0 + stretch.extra * pole_cos * pole_cos); };
  const auto n_of = [&](double r) { return 1.0 + refractivity(profile.at(h_of(r)).air_m3); };
  const double mu0 = x0.norm() > 0 ? x0.dot(d0) / x0.norm() : 1.0;  // cos(zenith angle) at the start
  const double invariant = n_of(r0) * r0 * std::sqrt(std::max(0.0, 1.0 - mu0 * mu0));
  // The radius the ray starts climbing from: the start, or below the horizon
  // its lowest point (n r = invariant), or the ground.
  double base = r0;
  bool descends = mu0 < 0;
  if (descends) {
    double lo = a, hi = r0;
    if (n_of(a) * a < invariant) {  // n r grows with r: the lowest point lies above the ground
      for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        (n_of(mid) * mid < invariant ? lo : hi) = mid;
      }
      base = hi;
    } else {
      base = a;
      ends_on_ground = true;
    }
  }
  PathColumns out;
  out.crosses = true;
  out.lowest_altitude_m = h_of(base);
  // Integrates from base up to r_end in u = sqrt(r - base) (the tangent's
  // 1/sqrt singularity made regular), cut at the levels.
  const auto climb = [&](double r_end) {
    std::vector<double> cuts{base, r_end};
    for (const ProfileLevel& l : profile.levels()) {
      const double r = a + l.altitude_m;
      if (r > base && r < r_end) cuts.push_back(r);
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const double ua = std::sqrt(cuts[i] - base), ub = std::sqrt(cuts[i + 1] - base);
      const double half = 0.5 * (ub - ua), mid = 0.5 * (ua + ub);
      PathSegment seg;
      double air_T = 0, air_p = 0;
      for (int g = 0; g < 4; ++g) {
        const double uu = mid + half * kGaussNodes[g];
        const double r = base + uu * uu;
        const Densities n = profile.at(h_of(r));
        const double nr = (1.0 + refractivity(n.air_m3)) * r;
        // ds = dr / cos(theta), cos^2 = 1 - (c / n r)^2 = (n r - c)(n r + c) / (n r)^2; dr = 2 u du
        const double cos2 = std::max((nr - invariant) * (nr + invariant), 0.0) / (nr * nr);
        const double w =
            cos2 > 0 ? kGaussWeights[g] * half * 2.0 * uu / std::sqrt(cos2) * length_scale : 0.0;
        add_node(n, w, seg, air_T, air_p);
        seg.length_m += w;
      }
      seg.mid_altitude_m = h_of(0.5 * (cuts[i] + cuts[i + 1]));
      seg.layer = profile.layer_of(seg.mid_altitude_m);
      add_segment(seg, air_T, air_p, keep, out);
    }
  };
  // Segments run from the start out: the leg down to the lowest point (or
  // the ground) is integrated upward, so its segments are reversed.
  if (descends) {
    climb(r0);
    std::reverse(out.segments.begin(), out.segments.end());
  }
  if (!ends_on_ground) climb(top);
  double along = 0;  // the segments' middles along the ray, from its start
  for (PathSegment& s : out.segments) {
    s.mid_distance_m = along + 0.5 * s.length_m;
    along += s.length_m;
  }
  return out;
}

double ray_traced_refraction_rad(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                                 const Vec3& apparent_direction) {
  const double a = earth.equatorial_radius_m, top = a + profile.top_altitude_m();
  const Vec3 x0 = from_m - earth.centre_m;
  const double r0 = x0.norm();
  const double mu0 = x0.dot(apparent_direction.normalized()) / r0;
  if (!(r0 < top) || !(mu0 >= 0)) return 0.0;
  const auto n_of = [&](double r) { return 1.0 + refractivity(profile.at(r - a).air_m3); };
  const double c = n_of(r0) * r0 * std::sqrt(std::max(0.0, 1.0 - mu0 * mu0));
  std::vector<double> cuts{r0, top};
  for (const ProfileLevel& l : profile.levels())
    if (a + l.altitude_m > r0 && a + l.altitude_m < top) cuts.push_back(a + l.altitude_m);
  std::sort(cuts.begin(), cuts.end());
  double bending = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    // u = sqrt(r - r0) keeps the horizontal start regular.
    const double ua = std::sqrt(cuts[i] - r0), ub = std::sqrt(cuts[i + 1] - r0);
    const double half = 0.5 * (ub - ua), mid = 0.5 * (ua + ub);
    for (int g = 0; g < 4; ++g) {
      const double u = mid + half * kGaussNodes[g], r = r0 + u * u;
      const double n = n_of(r), dn_dr = (n_of(r + 0.5) - n_of(r - 0.5));
      const double nr = n * r, s = (nr - c) * (nr + c);
      if (!(s > 0)) continue;
      bending += kGaussWeights[g] * half * 2.0 * u * (c / std::sqrt(s)) / n * (-dn_dr);
    }
  }
  return bending;
}

ChordRefraction chord_refraction(const AtmosphereProfile& profile, const EarthFigure& earth, const Vec3& from_m,
                                 const Vec3& apparent_direction, double range_m) {
  ChordRefraction out;
  const Stretch stretch(earth);
  const double a = earth.equatorial_radius_m, top = a + profile.top_altitude_m();
  const Vec3 x0 = stretch(from_m - earth.centre_m), u = stretch(apparent_direction.normalized()).normalized();
  const double r0 = x0.norm();
  if (!(r0 < top) || !(r0 > 0) || !(range_m > 0)) return out;
  // The plane of the centre, the start and the ray: radial and horizontal axes.
  const Vec3 e1 = x0 / r0;
  const Vec3 across = u - u.dot(e1) * e1;
  if (!(across.norm() > 1e-12)) return out;  // straight up: no bending
  using P2 = Eigen::Vector2d;
  const double pole_cos = x0.dot(earth.pole) / r0;
  const auto h_of = [&](double r) { return (r - a) / (1.0 + stretch.extra * pole_cos * pole_cos); };
  const auto n_of = [&](double r) { return 1.0 + refractivity(profile.at(h_of(r)).air_m3); };
  // d t / ds = (grad n / n) across the ray; grad n = dn/dr along the radius.
  const auto turn = [&](const P2& p, const P2& t) {
    const double r = p.norm();
    const double dn_dr = n_of(r + 0.5) - n_of(r - 0.5);
    const P2 e = p / r;
    return P2((dn_dr / n_of(r)) * (e - e.dot(t) * t));
  };
  const P2 p0(r0, 0.0), t0(u.dot(e1), u.dot(across.normalized()));
  P2 p = p0, t = t0;
  bool reached = false;
  const auto angle = [](const P2& x, const P2& y) { return std::atan2(std::fabs(x.x() * y.y() - x.y() * y.x()), x.dot(y)); };
  for (int step = 0; step < 100000; ++step) {
    const double r = p.norm();
    if (r >= top) break;
    if (h_of(r) < std::min(h_of(r0), 0.0) - 1e-6) {
      out.ends_on_ground = true;
      break;
    }
    // Steps of 50 m near the ground, longer higher up and along level rays.
    const double vertical = std::max(std::fabs(t.dot(p) / r), 0.02);
    const double ds = std::min((50.0 + 0.02 * std::max(h_of(r), 0.0)) / vertical, 5000.0);
    const P2 tm = (t + 0.5 * ds * turn(p, t)).normalized();
    const P2 pm = p + 0.5 * ds * t;
    const P2 next = p + ds * tm;
    if (!reached && (next - p0).norm() >= range_m) {
      // The point at the distance on this step (the chord length along the step's chord).
      const P2 q = p - p0;
      const double b = q.dot(tm), c = q.squaredNorm() - range_m * range_m;
      out.chord_rad = angle(t0, q + (-b + std::sqrt(std::max(b * b - c, 0.0))) * tm);
      reached = true;
    }
    t = (t + ds * turn(pm, tm)).normalized();
    p = next;
  }
  if (out.ends_on_ground) {
    if (!reached) out.chord_rad = angle(t0, p - p0);
    return out;
  }
  out.bending_rad = angle(t0, t);
  if (!reached) {  // beyond the top: straight on to the distance
    const P2 q = p - p0;
    const double b = q.dot(t), c = q.squaredNorm() - range_m * range_m;
    out.chord_rad = c < 0 ? angle(t0, q + (-b + std::sqrt(b * b - c)) * t) : angle(t0, q);
  }
  return out;
}

Vec3 to_sphere_space(const EarthFigure& earth, const Vec3& v) { return Stretch(earth)(v); }

double altitude_m(const EarthFigure& earth, const Vec3& point_m) {
  const Stretch stretch(earth);
  const Vec3 x = stretch(point_m - earth.centre_m);
  return corrected_altitude(x.norm(), x.dot(earth.pole), earth.equatorial_radius_m, stretch.extra);
}

}  // namespace eoir::atmosphere
