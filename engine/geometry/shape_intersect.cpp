// Analytic ray/shape intersection in double precision (spec 4.1.3, 4.1.5.1).
//
// Robustness (DESIGN.md section 3): every ray is first moved to its point of
// closest approach to the part origin (t0 = -o.d), so the quadratics below see
// small coefficients whatever the range (a 1 m part at 10 km, the Moon at
// 400,000 km); quadratics use the stable root pair q/A, C/q; the ellipsoid is
// scaled to the unit sphere and its discriminant is 1 - |l|^2 with l the
// perpendicular from the centre (no b^2 - ac cancellation). Closed shapes are
// convex, so each is the intersection of slabs / a quadric region and the hit
// is the entry of the ray's interval: only outward-facing surfaces are seen.
#include "geometry/shape_intersect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define EOIR_AVX_SPHEROID 1
#endif

#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::geometry {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = constants::pi;
constexpr double kInsideTolerance = 1e-9;  // relative depth for "observer inside"

// Sphere / ellipsoid of revolution, ray already shifted near the centre.
bool hit_spheroid(double a, double c, const Vec3& o, const Vec3& d, double t_min, double t_max, double& t,
                  Vec3& n) {
  const double inv_a = 1.0 / a, inv_c = 1.0 / c;
  const Vec3 os(o.x() * inv_a, o.y() * inv_a, o.z() * inv_c);
  const Vec3 ds(d.x() * inv_a, d.y() * inv_a, d.z() * inv_c);
  const double len = ds.norm();  // scaled parameter = t * len
  const double inv_len = 1.0 / len;
  const Vec3 dh = ds * inv_len;
  const double b = os.dot(dh);
  const Vec3 l = os - b * dh;  // perpendicular from the centre (scaled units)
  const double ll = l.norm();
  const double disc = (1.0 - ll) * (1.0 + ll);
  if (!(disc >= 0.0)) return false;  // also rejects NaN
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  const double cc = (os.squaredNorm() - 1.0);
  double entry = q;  // scaled units
  if (q != 0.0) entry = std::min(q, cc / q);
  const double tt = entry * inv_len;
  if (!(tt > t_min && tt < t_max)) return false;
  const Vec3 p = o + tt * d;
  const Vec3 gradient(p.x() * (inv_a * inv_a), p.y() * (inv_a * inv_a), p.z() * (inv_c * inv_c));
  n = gradient * (1.0 / gradient.norm());
  t = tt;
  return true;
}

bool hit_box(const ShapeGeom& g, const Vec3& o, const Vec3& d, double t_min, double t_max, double& t, Vec3& n) {
  const Vec3 h(0.5 * g.x_m, 0.5 * g.y_m, 0.5 * g.z_m);
  double t_enter = -kInf, t_exit = kInf;
  int axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (std::abs(o[i]) > h[i]) return false;
      continue;
    }
    const double t1 = (-h[i] - o[i]) / d[i], t2 = (h[i] - o[i]) / d[i];
    const double near = std::min(t1, t2), far = std::max(t1, t2);
    if (near > t_enter) {
      t_enter = near;
      axis = i;
    }
    t_exit = std::min(t_exit, far);
  }
  if (axis < 0 || t_enter > t_exit || !(t_enter > t_min && t_enter < t_max)) return false;
  n = Vec3::Zero();
  n[axis] = d[axis] > 0 ? -1.0 : 1.0;
  t = t_enter;
  return true;
}

bool hit_plate(const ShapeGeom& g, const Vec3& o, const Vec3& d, double t_min, double t_max, double& t, Vec3& n) {
  if (d.z() == 0.0) return false;  // edge-on
  const double tt = -o.z() / d.z();
  if (!(tt > t_min && tt < t_max)) return false;
  const Vec3 p = o + tt * d;
  if (std::abs(p.x()) > 0.5 * g.x_m || std::abs(p.y()) > 0.5 * g.y_m) return false;
  n = Vec3(0, 0, d.z() > 0 ? -1.0 : 1.0);  // two-sided: the face the ray sees
  t = tt;
  return true;
}

// Frustum rho <= r(z) = rm + k z, |z| <= L/2 (cylinder k = 0, cone r_top = 0).
// Within the slab r(z) >= 0, so rho <= r(z) <=> Q(t) = A t^2 + 2 B t + C <= 0.
bool hit_frustum(const ShapeGeom& g, const Vec3& o, const Vec3& d, double t_min, double t_max, double& t,
                 Vec3& n) {
  const double h = 0.5 * g.length_m;
  const double rm = 0.5 * (g.r_top_m + g.r_bottom_m);
  const double k = (g.r_top_m - g.r_bottom_m) / g.length_m;
  double lo = -kInf, hi = kInf;
  if (d.z() == 0.0) {
    if (std::abs(o.z()) > h) return false;
  } else {
    const double t1 = (-h - o.z()) / d.z(), t2 = (h - o.z()) / d.z();
    lo = std::min(t1, t2);
    hi = std::max(t1, t2);
  }
  bool side = false;  // entry through the side (else through a cap)
  const double w0 = rm + k * o.z();
  const double A = d.x() * d.x() + d.y() * d.y() - k * k * d.z() * d.z();
  const double B = o.x() * d.x() + o.y() * d.y() - k * d.z() * w0;
  const double C = o.x() * o.x() + o.y() * o.y() - w0 * w0;
  if (A == 0.0) {  // linear: 2 B t + C <= 0
    if (B > 0.0) {
      hi = std::min(hi, -C / (2.0 * B));
    } else if (B < 0.0) {
      const double tt = -C / (2.0 * B);
      if (tt > lo) {
        lo = tt;
        side = true;
      }
    } else if (C > 0.0) {
      return false;
    }
  } else {
    const double disc = B * B - A * C;
    if (A > 0.0) {
      if (!(disc >= 0.0)) return false;
      const double q = -(B + std::copysign(std::sqrt(disc), B));
      double r1 = q / A, r2 = r1;
      if (q != 0.0) r2 = C / q;
      if (r1 > r2) std::swap(r1, r2);
      if (r1 > lo) {
        lo = r1;
        side = true;
      }
      hi = std::min(hi, r2);
    } else if (disc >= 0.0) {  // A < 0: Q <= 0 outside [r1, r2]
      const double q = -(B + std::copysign(std::sqrt(disc), B));
      double r1 = q / A, r2 = r1;
      if (q != 0.0) r2 = C / q;
      if (r1 > r2) std::swap(r1, r2);
      if (lo <= std::min(hi, r1)) {
        hi = std::min(hi, r1);
      } else if (r2 > lo) {
        lo = r2;
        side = true;
      }
    }  // A < 0 and no real root: Q < 0 on the whole slab segment
  }
  if (!(lo <= hi) || !(lo > t_min && lo < t_max)) return false;
  if (side) {
    const Vec3 p = o + lo * d;
    const double rho = std::hypot(p.x(), p.y());
    n = rho > 0.0 ? Vec3(p.x() / rho, p.y() / rho, -k).normalized() : Vec3(0, 0, 1);
  } else {
    n = Vec3(0, 0, d.z() > 0 ? -1.0 : 1.0);
  }
  t = lo;
  return true;
}

// asinh(x)/x (s = +1) or asin(x)/x (s = -1), series near 0.
double arc_ratio(double x, double s) {
  if (x < 1e-3) return 1.0 - s * x * x / 6.0 + 3.0 * x * x * x * x / 40.0;
  return s > 0 ? std::asinh(x) / x : std::asin(x) / x;
}

// The plume's tangent cone as a cone in its own frame, whose origin lies at
// z_centre of the plume's frame.
ShapeGeom plume_cone(const ShapeGeom& g, double& z_centre) {
  const PlumeProfile p = plume_profile(g);
  ShapeGeom c;
  c.kind = ShapeKind::cone;
  c.r_bottom_m = p.tangent_radius_m;
  c.r_top_m = 0.0;
  c.length_m = p.apex_z_m - p.tangent_z_m;
  z_centre = 0.5 * (p.apex_z_m + p.tangent_z_m);
  return c;
}

// Union of the sphere and its tangent cone (a convex solid): the nearer
// entry of the two, dropping an entry that lies inside the other.
bool hit_plume(const ShapeGeom& g, const Vec3& o, const Vec3& d, double t_min, double t_max, double& t, Vec3& n) {
  double zc = 0;
  const ShapeGeom cone = plume_cone(g, zc);
  const Vec3 shift(0, 0, zc);
  double ts = 0, tc = 0;
  Vec3 ns = Vec3::Zero(), nc = Vec3::Zero();
  bool s = hit_spheroid(g.a_m, g.a_m, o, d, t_min, t_max, ts, ns);
  if (s && shape_contains(cone, o + ts * d - shift)) s = false;
  bool c = hit_frustum(cone, o - shift, d, t_min, t_max, tc, nc);
  if (c && (o + tc * d).squaredNorm() < g.a_m * g.a_m * (1.0 - 1e-9)) c = false;
  if (!s && !c) return false;
  if (s && (!c || ts <= tc)) {
    t = ts;
    n = ns;
  } else {
    t = tc;
    n = nc;
  }
  return true;
}

}  // namespace

PlumeProfile plume_profile(const ShapeGeom& g) {
  // Apex at h = length - r from the centre; the tangent circle at z = r^2 / h,
  // radius r sqrt(1 - r^2 / h^2); the tangent length sqrt(h^2 - r^2).
  PlumeProfile p;
  const double r = g.a_m;
  p.apex_z_m = g.length_m - r;
  p.tangent_z_m = r * r / p.apex_z_m;
  p.tangent_radius_m = r * std::sqrt(std::max(0.0, 1.0 - (r / p.apex_z_m) * (r / p.apex_z_m)));
  return p;
}

ShapeGeom shape_geom(ShapeKind kind, const std::vector<double>& d, const std::string& field) {
  if (kind == ShapeKind::composite)
    throw Error(Status::out_of_range, field + ": a composite is made of simple shapes, not one");
  if (kind == ShapeKind::mesh) throw Error(Status::out_of_range, field + ": a mesh needs its model file");
  universe::check_dimensions(kind, d, field);
  ShapeGeom g;
  g.kind = kind;
  switch (g.kind) {
    case ShapeKind::sphere: g.a_m = g.c_m = d[0]; break;
    case ShapeKind::oblate: g.a_m = d[0]; g.c_m = d[1]; break;
    case ShapeKind::box: g.x_m = d[0]; g.y_m = d[1]; g.z_m = d[2]; break;
    case ShapeKind::plate: g.x_m = d[0]; g.y_m = d[1]; break;
    case ShapeKind::cylinder: g.r_bottom_m = g.r_top_m = d[0]; g.length_m = d[1]; break;
    case ShapeKind::cone: g.r_bottom_m = d[0]; g.r_top_m = 0.0; g.length_m = d[1]; break;
    case ShapeKind::coupler: g.r_bottom_m = d[0]; g.r_top_m = d[1]; g.length_m = d[2]; break;
    case ShapeKind::plume: g.a_m = g.c_m = d[0]; g.length_m = d[1]; break;
    case ShapeKind::none:
    case ShapeKind::composite:
    case ShapeKind::mesh: break;
  }
  return g;
}

bool intersect_shape(const ShapeGeom& g, const Vec3& origin_m, const Vec3& dir, double t_min, double t_max,
                     double& t_m, Vec3& normal, std::int32_t* facet) {
  if (g.kind == ShapeKind::none) return false;
  if (g.kind == ShapeKind::mesh) {
    std::int32_t f = -1;
    if (!g.mesh->intersect(g.mesh_group, origin_m, dir, t_min, t_max, t_m, normal, f)) return false;
    if (facet) *facet = f;
    return true;
  }
  if (facet) *facet = -1;
  // Move the origin to the closest approach to the part origin (small numbers).
  const double t0 = -origin_m.dot(dir);
  const Vec3 o = origin_m + t0 * dir;
  const double lo = t_min - t0, hi = t_max - t0;
  double t = 0;
  bool hit = false;
  switch (g.kind) {
    case ShapeKind::sphere:
    case ShapeKind::oblate: hit = hit_spheroid(g.a_m, g.c_m, o, dir, lo, hi, t, normal); break;
    case ShapeKind::box: hit = hit_box(g, o, dir, lo, hi, t, normal); break;
    case ShapeKind::plate: hit = hit_plate(g, o, dir, lo, hi, t, normal); break;
    case ShapeKind::cylinder:
    case ShapeKind::cone:
    case ShapeKind::coupler: hit = hit_frustum(g, o, dir, lo, hi, t, normal); break;
    case ShapeKind::plume: hit = hit_plume(g, o, dir, lo, hi, t, normal); break;
    case ShapeKind::none:
    case ShapeKind::composite:
    case ShapeKind::mesh: break;
  }
  if (!hit) return false;
  t_m = t0 + t;
  return t_m > t_min && t_m < t_max;
}

namespace {

#ifdef EOIR_AVX_SPHEROID
const bool kHasAvx = [] {
  __builtin_cpu_init();  // (this may run before the library's own initialisers)
  return __builtin_cpu_supports("avx") != 0;
}();

// (x x + y y) + z z, as Eigen's squaredNorm of a 3-vector.
__attribute__((target("avx"))) inline __m256d norm2(__m256d x, __m256d y, __m256d z) {
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(x, x), _mm256_mul_pd(y, y)), _mm256_mul_pd(z, z));
}

// intersect_shape's closest approach and hit_spheroid on rays i .. i + 3,
// lane by lane the scalar code's operations (Eigen's 3-vector dot product
// and norm sum (x + y) + z).
__attribute__((target("avx"))) void spheroid_rays4(double a, double c, const Vec3& origin, const Vec3* dir,
                                                   const double* t_max, bool* hit, double* t_m, Vec3* normal) {
  const __m256d dx = _mm256_set_pd(dir[3].x(), dir[2].x(), dir[1].x(), dir[0].x());
  const __m256d dy = _mm256_set_pd(dir[3].y(), dir[2].y(), dir[1].y(), dir[0].y());
  const __m256d dz = _mm256_set_pd(dir[3].z(), dir[2].z(), dir[1].z(), dir[0].z());
  const __m256d ox0 = _mm256_set1_pd(origin.x()), oy0 = _mm256_set1_pd(origin.y()), oz0 = _mm256_set1_pd(origin.z());
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  // t0 = -origin.d; o = origin + t0 d; [lo, hi) = [0 - t0, t_max - t0)
  const __m256d dot =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ox0, dx), _mm256_mul_pd(oy0, dy)), _mm256_mul_pd(oz0, dz));
  const __m256d sign = _mm256_set1_pd(-0.0);
  const __m256d t0 = _mm256_xor_pd(dot, sign);
  const __m256d ox = _mm256_add_pd(ox0, _mm256_mul_pd(t0, dx)), oy = _mm256_add_pd(oy0, _mm256_mul_pd(t0, dy)),
                oz = _mm256_add_pd(oz0, _mm256_mul_pd(t0, dz));
  const __m256d tmax = _mm256_loadu_pd(t_max);
  const __m256d lo = _mm256_sub_pd(zero, t0), hi = _mm256_sub_pd(tmax, t0);
  const double inv_a_s = 1.0 / a, inv_c_s = 1.0 / c;
  const __m256d inv_a = _mm256_set1_pd(inv_a_s), inv_c = _mm256_set1_pd(inv_c_s);
  const __m256d osx = _mm256_mul_pd(ox, inv_a), osy = _mm256_mul_pd(oy, inv_a), osz = _mm256_mul_pd(oz, inv_c);
  const __m256d dsx = _mm256_mul_pd(dx, inv_a), dsy = _mm256_mul_pd(dy, inv_a), dsz = _mm256_mul_pd(dz, inv_c);
  const __m256d len = _mm256_sqrt_pd(norm2(dsx, dsy, dsz));
  const __m256d inv_len = _mm256_div_pd(one, len);
  const __m256d dhx = _mm256_mul_pd(dsx, inv_len), dhy = _mm256_mul_pd(dsy, inv_len), dhz = _mm256_mul_pd(dsz, inv_len);
  const __m256d b =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(osx, dhx), _mm256_mul_pd(osy, dhy)), _mm256_mul_pd(osz, dhz));
  const __m256d lx = _mm256_sub_pd(osx, _mm256_mul_pd(b, dhx)), ly = _mm256_sub_pd(osy, _mm256_mul_pd(b, dhy)),
                lz = _mm256_sub_pd(osz, _mm256_mul_pd(b, dhz));
  const __m256d ll = _mm256_sqrt_pd(norm2(lx, ly, lz));
  const __m256d disc = _mm256_mul_pd(_mm256_sub_pd(one, ll), _mm256_add_pd(one, ll));
  const __m256d real = _mm256_cmp_pd(disc, zero, _CMP_GE_OQ);  // (NaN: false)
  // q = -(b + copysign(sqrt(disc), b))
  const __m256d root = _mm256_or_pd(_mm256_andnot_pd(sign, _mm256_sqrt_pd(disc)), _mm256_and_pd(sign, b));
  const __m256d q = _mm256_xor_pd(_mm256_add_pd(b, root), sign);
  const __m256d cc = _mm256_sub_pd(norm2(osx, osy, osz), one);
  // entry = q != 0 ? std::min(q, cc / q) : q, std::min(x, y) being y < x ? y : x
  const __m256d ratio = _mm256_div_pd(cc, q);
  const __m256d smaller = _mm256_blendv_pd(q, ratio, _mm256_cmp_pd(ratio, q, _CMP_LT_OQ));
  const __m256d entry = _mm256_blendv_pd(q, smaller, _mm256_cmp_pd(q, zero, _CMP_NEQ_UQ));
  const __m256d tt = _mm256_mul_pd(entry, inv_len);
  const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(tt, lo, _CMP_GT_OQ), _mm256_cmp_pd(tt, hi, _CMP_LT_OQ));
  const __m256d px = _mm256_add_pd(ox, _mm256_mul_pd(tt, dx)), py = _mm256_add_pd(oy, _mm256_mul_pd(tt, dy)),
                pz = _mm256_add_pd(oz, _mm256_mul_pd(tt, dz));
  const __m256d gaa = _mm256_set1_pd(inv_a_s * inv_a_s), gcc = _mm256_set1_pd(inv_c_s * inv_c_s);
  const __m256d gx = _mm256_mul_pd(px, gaa), gy = _mm256_mul_pd(py, gaa), gz = _mm256_mul_pd(pz, gcc);
  const __m256d inv_g = _mm256_div_pd(one, _mm256_sqrt_pd(norm2(gx, gy, gz)));
  const __m256d t = _mm256_add_pd(t0, tt);  // t_m = t0 + t
  const __m256d in_range = _mm256_and_pd(_mm256_cmp_pd(t, zero, _CMP_GT_OQ), _mm256_cmp_pd(t, tmax, _CMP_LT_OQ));
  const int mask = _mm256_movemask_pd(_mm256_and_pd(_mm256_and_pd(real, inside), in_range));
  alignas(32) double tv[4], nx[4], ny[4], nz[4];
  _mm256_store_pd(tv, t);
  _mm256_store_pd(nx, _mm256_mul_pd(gx, inv_g));
  _mm256_store_pd(ny, _mm256_mul_pd(gy, inv_g));
  _mm256_store_pd(nz, _mm256_mul_pd(gz, inv_g));
  for (int k = 0; k < 4; ++k) {
    hit[k] = (mask >> k) & 1;
    if (!hit[k]) continue;
    t_m[k] = tv[k];
    normal[k] = Vec3(nx[k], ny[k], nz[k]);
  }
}
#endif

}  // namespace

void intersect_spheroid_rays(const ShapeGeom& g, const Vec3& origin_m, const Vec3* dir, int n, const double* t_max,
                             bool* hit, double* t_m, Vec3* normal) {
  if (g.kind != ShapeKind::sphere && g.kind != ShapeKind::oblate)
    throw Error(Status::internal, "intersect_spheroid_rays: not a sphere or spheroid");
  int i = 0;
#ifdef EOIR_AVX_SPHEROID
  if (kHasAvx)
    for (; i + 4 <= n; i += 4) spheroid_rays4(g.a_m, g.c_m, origin_m, dir + i, t_max + i, hit + i, t_m + i, normal + i);
#endif
  for (; i < n; ++i) hit[i] = intersect_shape(g, origin_m, dir[i], 0.0, t_max[i], t_m[i], normal[i]);
}

bool shape_contains(const ShapeGeom& g, const Vec3& p) {
  const double f = 1.0 - kInsideTolerance;
  switch (g.kind) {
    case ShapeKind::sphere:
    case ShapeKind::oblate: {
      const Vec3 s(p.x() / g.a_m, p.y() / g.a_m, p.z() / g.c_m);
      return s.squaredNorm() < f * f;
    }
    case ShapeKind::box:
      return std::abs(p.x()) < 0.5 * g.x_m * f && std::abs(p.y()) < 0.5 * g.y_m * f &&
             std::abs(p.z()) < 0.5 * g.z_m * f;
    case ShapeKind::cylinder:
    case ShapeKind::cone:
    case ShapeKind::coupler: {
      const double h = 0.5 * g.length_m;
      if (!(std::abs(p.z()) < h * f)) return false;
      const double r = 0.5 * (g.r_top_m + g.r_bottom_m) + (g.r_top_m - g.r_bottom_m) / g.length_m * p.z();
      return std::hypot(p.x(), p.y()) < r - kInsideTolerance * std::max(g.r_bottom_m, g.r_top_m);
    }
    case ShapeKind::mesh: return g.mesh->contains(p);
    case ShapeKind::plume: {
      if (p.squaredNorm() < g.a_m * g.a_m * f * f) return true;
      double zc = 0;
      const ShapeGeom cone = plume_cone(g, zc);
      return shape_contains(cone, p - Vec3(0, 0, zc));
    }
    case ShapeKind::plate:
    case ShapeKind::none:
    case ShapeKind::composite: return false;
  }
  return false;
}

double shape_bounding_radius_m(const ShapeGeom& g) {
  switch (g.kind) {
    case ShapeKind::sphere:
    case ShapeKind::oblate: return std::max(g.a_m, g.c_m);
    case ShapeKind::box: return 0.5 * std::sqrt(g.x_m * g.x_m + g.y_m * g.y_m + g.z_m * g.z_m);
    case ShapeKind::plate: return 0.5 * std::hypot(g.x_m, g.y_m);
    case ShapeKind::cylinder:
    case ShapeKind::cone:
    case ShapeKind::coupler:
      return std::max(std::hypot(g.r_bottom_m, 0.5 * g.length_m), std::hypot(g.r_top_m, 0.5 * g.length_m));
    case ShapeKind::mesh: return g.mesh->bounding_radius_m(g.mesh_group);
    case ShapeKind::plume: return std::max(g.a_m, g.length_m - g.a_m);
    case ShapeKind::none:
    case ShapeKind::composite: return 0.0;
  }
  return 0.0;
}

double spheroid_zone_area_m2(double a, double c, double u1, double u2) {
  // A = 2 pi a [G(u2) - G(u1)], G(u) = int_0^u sqrt(c^2 + (a^2 - c^2) v^2) dv, u = sin(beta).
  const double kk = a * a - c * c;
  const double s = kk >= 0 ? 1.0 : -1.0;
  const auto G = [&](double u) {
    const double x = std::sqrt(std::abs(kk)) * std::abs(u) / c;
    return 0.5 * u * std::sqrt(c * c + kk * u * u) + 0.5 * c * u * arc_ratio(x, s);
  };
  return 2.0 * kPi * a * (G(u2) - G(u1));
}

double shape_surface_area_m2(const ShapeGeom& g) {
  switch (g.kind) {
    case ShapeKind::sphere:
    case ShapeKind::oblate: return spheroid_zone_area_m2(g.a_m, g.c_m, -1.0, 1.0);
    case ShapeKind::box: return 2.0 * (g.x_m * g.y_m + g.y_m * g.z_m + g.z_m * g.x_m);
    case ShapeKind::plate: return 2.0 * g.x_m * g.y_m;
    case ShapeKind::cylinder:
    case ShapeKind::cone:
    case ShapeKind::coupler: {
      const double r1 = g.r_bottom_m, r2 = g.r_top_m;
      return kPi * (r1 + r2) * std::hypot(r1 - r2, g.length_m) + kPi * (r1 * r1 + r2 * r2);
    }
    case ShapeKind::mesh: return g.mesh->surface_area_m2(g.mesh_group);
    case ShapeKind::plume: {  // the sphere below the tangent circle, 2 pi r (r + z_t), and the cone's side, pi rho_t s
      const PlumeProfile p = plume_profile(g);
      const double h = p.apex_z_m, r = g.a_m;
      return 2.0 * kPi * r * (r + p.tangent_z_m) + kPi * p.tangent_radius_m * std::sqrt(h * h - r * r);
    }
    case ShapeKind::none:
    case ShapeKind::composite: return 0.0;
  }
  return 0.0;
}

int box_face(const ShapeGeom& g, const Vec3& p) {
  const Vec3 h(0.5 * g.x_m, 0.5 * g.y_m, 0.5 * g.z_m);
  int axis = 0;
  double best = -kInf;
  for (int i = 0; i < 3; ++i) {
    const double v = std::abs(p[i]) / h[i];
    if (v > best) {
      best = v;
      axis = i;
    }
  }
  return 2 * axis + (p[axis] < 0 ? 1 : 0);
}

int frustum_face(const ShapeGeom& g, const Vec3& p) {
  const double h = 0.5 * g.length_m;
  const double k = (g.r_top_m - g.r_bottom_m) / g.length_m;
  const double r = 0.5 * (g.r_top_m + g.r_bottom_m) + k * p.z();
  const double rho = std::hypot(p.x(), p.y());
  int face = 0;
  double best = std::abs(rho - r) / std::sqrt(1.0 + k * k);
  if (std::abs(p.z() + h) < best && rho <= g.r_bottom_m * (1 + 1e-9)) {
    best = std::abs(p.z() + h);
    face = 1;
  }
  if (g.r_top_m > 0 && std::abs(p.z() - h) < best && rho <= g.r_top_m * (1 + 1e-9)) face = 2;
  return face;
}

Vec3 shape_normal(const ShapeGeom& g, const Vec3& p) {
  switch (g.kind) {
    case ShapeKind::sphere:
    case ShapeKind::oblate:
      return Vec3(p.x() / (g.a_m * g.a_m), p.y() / (g.a_m * g.a_m), p.z() / (g.c_m * g.c_m)).normalized();
    case ShapeKind::box: {
      const int f = box_face(g, p);
      Vec3 n = Vec3::Zero();
      n[f / 2] = (f % 2) ? -1.0 : 1.0;
      return n;
    }
    case ShapeKind::plate: return Vec3(0, 0, p.z() >= 0 ? 1.0 : -1.0);
    case ShapeKind::cylinder:
    case ShapeKind::cone:
    case ShapeKind::coupler: {
      const int f = frustum_face(g, p);
      if (f == 1) return Vec3(0, 0, -1);
      if (f == 2) return Vec3(0, 0, 1);
      const double rho = std::hypot(p.x(), p.y());
      const double k = (g.r_top_m - g.r_bottom_m) / g.length_m;
      return rho > 0 ? Vec3(p.x() / rho, p.y() / rho, -k).normalized() : Vec3(0, 0, 1);
    }
    case ShapeKind::mesh: return g.mesh->normal(g.mesh->nearest_triangle(g.mesh_group, p));
    case ShapeKind::plume: {
      const PlumeProfile pp = plume_profile(g);
      if (p.z() <= pp.tangent_z_m) return p.norm() > 0 ? Vec3(p.normalized()) : Vec3(0, 0, -1);
      const double rho = std::hypot(p.x(), p.y());
      const double k = pp.tangent_radius_m / (pp.apex_z_m - pp.tangent_z_m);  // the cone's dr/dz, negated
      return rho > 0 ? Vec3(p.x() / rho, p.y() / rho, k).normalized() : Vec3(0, 0, 1);
    }
    case ShapeKind::none:
    case ShapeKind::composite: break;
  }
  return Vec3::UnitZ();
}

}  // namespace eoir::geometry
