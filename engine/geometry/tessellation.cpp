// Surface tessellation into patches dA of about equal area (spec 4.1.5.2) and
// the O(1) rule mapping a surface point to its patch.
//
// Every cell's area is exact, so the patches of a part sum to its surface area.
//  - sphere / oblate: n_lat bands of equal parametric-latitude height beta
//    (z = c sin beta, rho = a cos beta); band i split into n_lon(i) equal
//    longitude cells with n_lon ~ band area / target^2. Exact zone areas.
//    grid[part] = {n_lat, off_0, ..., off_n_lat} (band offsets in the part).
//  - box: each face a rectangular grid; grid = 6 x {nu, nv, off}, face order
//    +x -x +y -y +z -z, face axis i has u = (i+1)%3, v = (i+2)%3.
//  - plate: two faces (+z then -z), same grid; grid = 2 x {nu, nv, off}.
//  - cylinder / cone / coupler: side grid in (angle, slant) with rings of
//    equal area (height of each ring from the frustum's area law), caps in
//    (r^2 for equal area, angle); grid = {side, bottom cap, top cap} x
//    {n_angle, n_radial, off} (n_angle = 0: no such cap, the cone's top).
//  - mesh: one patch per triangle of the part's group (the model's own
//    tessellation, whatever the target), two (front, back) on open sheets;
//    grid = each triangle's first patch in the part.
//  - plume: the sphere below the tangent circle in latitude bands as the
//    sphere's (the last band ends at the tangent circle), then the cone's
//    side as a cone's; grid = {n_lat, off_0, ..., off_n_lat, n_angle,
//    n_slant, off}.
//  - none: no patches.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "geometry/scene_geometry.hpp"
#include "geometry/tessellation.hpp"

namespace eoir::geometry {
namespace {

using constants::pi;
constexpr double kMaxPatchesPerPart = 4.0e6;  // guards against absurd targets

int count_for(double length_m, double target_m) {
  return static_cast<int>(std::max(1.0, std::round(length_m / target_m)));
}

int clamp_index(double v, int n) {
  if (!(v >= 0.0)) return 0;  // also NaN
  return std::min(n - 1, static_cast<int>(v));
}

// Angle in [0, 2 pi).
double azimuth(double x, double y) {
  double phi = std::atan2(y, x);
  if (phi < 0) phi += 2.0 * pi;
  return phi;
}

void add_patch(Tessellation& t, std::int32_t part, const ShapePart& sp, const Vec3& centre_part,
               const Vec3& normal_part, double area) {
  const Mat3 r = sp.orientation.toRotationMatrix();
  Patch p;
  p.part = part;
  p.centre_body_m = sp.offset_m + r * centre_part;
  p.normal_body = (r * normal_part).normalized();
  p.area_m2 = area;
  t.patches.push_back(p);
}

void tessellate_spheroid(Tessellation& t, std::int32_t part, const ShapePart& sp, const ShapeGeom& g, double target,
                         std::vector<std::int32_t>& grid) {
  const double a = g.a_m, c = g.c_m;
  const int n_lat = count_for(0.5 * pi * (a + c), target);
  const double dbeta = pi / n_lat;
  grid.push_back(n_lat);
  std::int32_t off = 0;
  grid.push_back(off);
  for (int i = 0; i < n_lat; ++i) {
    const double b1 = -0.5 * pi + i * dbeta, b2 = (i + 1 == n_lat) ? 0.5 * pi : b1 + dbeta;
    const double band = spheroid_zone_area_m2(a, c, std::sin(b1), std::sin(b2));
    const int n_lon = static_cast<int>(std::max(1.0, std::round(band / (target * target))));
    const double bm = 0.5 * (b1 + b2);
    for (int j = 0; j < n_lon; ++j) {
      Vec3 centre;
      if (n_lon == 1 && (i == 0 || i + 1 == n_lat)) {  // single-cell cap: its centre is the pole
        centre = n_lat == 1 ? Vec3(a, 0, 0) : Vec3(0, 0, i == 0 ? -c : c);
      } else {
        const double lam = (j + 0.5) * 2.0 * pi / n_lon;
        centre = Vec3(a * std::cos(bm) * std::cos(lam), a * std::cos(bm) * std::sin(lam), c * std::sin(bm));
      }
      add_patch(t, part, sp, centre, shape_normal(g, centre), band / n_lon);
    }
    off += n_lon;
    grid.push_back(off);
  }
}

// Rectangular grid on the face of axis `axis` at p[axis] = sign * half[axis].
void tessellate_face(Tessellation& t, std::int32_t part, const ShapePart& sp, const Vec3& half, int axis, double sign,
                     double target, std::vector<std::int32_t>& grid, std::int32_t& off) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int nu = count_for(2 * half[u], target), nv = count_for(2 * half[v], target);
  const double du = 2 * half[u] / nu, dv = 2 * half[v] / nv;
  grid.insert(grid.end(), {nu, nv, off});
  Vec3 n = Vec3::Zero();
  n[axis] = sign;
  for (int iv = 0; iv < nv; ++iv)
    for (int iu = 0; iu < nu; ++iu) {
      Vec3 c = Vec3::Zero();
      c[axis] = sign * half[axis];
      c[u] = -half[u] + (iu + 0.5) * du;
      c[v] = -half[v] + (iv + 0.5) * dv;
      add_patch(t, part, sp, c, n, du * dv);
    }
  off += nu * nv;
}

// Slant coordinate w in [0, 1] (0 at the bottom) below which lies the fraction
// f of the frustum's side area: rb w + (rt - rb) w^2 / 2 = f (rb + rt) / 2.
double frustum_w(double rb, double rt, double f) {
  const double rhs = f * 0.5 * (rb + rt);
  return 2.0 * rhs / (rb + std::sqrt(std::max(0.0, rb * rb + 2.0 * (rt - rb) * rhs)));
}
double frustum_f(double rb, double rt, double w) { return (rb * w + 0.5 * (rt - rb) * w * w) / (0.5 * (rb + rt)); }

void tessellate_cap(Tessellation& t, std::int32_t part, const ShapePart& sp, double radius, double z, double nz,
                    double target, std::vector<std::int32_t>& grid, std::int32_t& off) {
  if (!(radius > 0)) {
    grid.insert(grid.end(), {0, 0, off});
    return;
  }
  const int n_r = count_for(radius, target);
  const double area = pi * radius * radius;
  const int n_a = static_cast<int>(std::max(1.0, std::round(area / (n_r * target * target))));
  grid.insert(grid.end(), {n_a, n_r, off});
  for (int i = 0; i < n_r; ++i)
    for (int j = 0; j < n_a; ++j) {
      const double r = (i == 0 && n_a == 1) ? 0.0 : radius * std::sqrt((i + 0.5) / n_r);
      const double phi = (j + 0.5) * 2.0 * pi / n_a;
      add_patch(t, part, sp, Vec3(r * std::cos(phi), r * std::sin(phi), z), Vec3(0, 0, nz), area / (n_r * n_a));
    }
  off += n_r * n_a;
}

void tessellate_frustum(Tessellation& t, std::int32_t part, const ShapePart& sp, const ShapeGeom& g, double target,
                        std::vector<std::int32_t>& grid) {
  const double rb = g.r_bottom_m, rt = g.r_top_m, len = g.length_m, h = 0.5 * len;
  const double slant = std::hypot(rb - rt, len);
  const double side = pi * (rb + rt) * slant;
  const int n_h = count_for(slant, target);
  const int n_a = static_cast<int>(std::max(1.0, std::round(side / (n_h * target * target))));
  grid.insert(grid.end(), {n_a, n_h, 0});
  for (int i = 0; i < n_h; ++i) {
    const double w = frustum_w(rb, rt, (i + 0.5) / n_h);
    const double z = -h + w * len, r = rb + (rt - rb) * w;
    for (int j = 0; j < n_a; ++j) {
      const double phi = (j + 0.5) * 2.0 * pi / n_a;
      const Vec3 c(r * std::cos(phi), r * std::sin(phi), z);
      const Vec3 n = Vec3(std::cos(phi), std::sin(phi), -(rt - rb) / len).normalized();
      add_patch(t, part, sp, c, n, side / (n_h * n_a));
    }
  }
  std::int32_t off = n_h * n_a;
  tessellate_cap(t, part, sp, rb, -h, -1.0, target, grid, off);
  tessellate_cap(t, part, sp, rt, h, 1.0, target, grid, off);
}

void tessellate_plume(Tessellation& t, std::int32_t part, const ShapePart& sp, const ShapeGeom& g, double target,
                      std::vector<std::int32_t>& grid) {
  const PlumeProfile pp = plume_profile(g);
  const double r = g.a_m;
  const double beta_t = std::asin(std::clamp(pp.tangent_z_m / r, -1.0, 1.0));
  // (At least 3 bands of 8 cells, and 8 cells around the cone: coarse
  // targets still face every way.)
  const int n_lat = std::max(3, count_for(r * (beta_t + 0.5 * pi), target));
  const double dbeta = (beta_t + 0.5 * pi) / n_lat;
  grid.push_back(n_lat);
  std::int32_t off = 0;
  grid.push_back(off);
  for (int i = 0; i < n_lat; ++i) {
    const double b1 = -0.5 * pi + i * dbeta, b2 = (i + 1 == n_lat) ? beta_t : b1 + dbeta;
    const double band = 2.0 * pi * r * r * (std::sin(b2) - std::sin(b1));  // a sphere's zone: 2 pi r dz
    const int n_lon = static_cast<int>(std::max(8.0, std::round(band / (target * target))));
    const double bm = 0.5 * (b1 + b2);
    for (int j = 0; j < n_lon; ++j) {
      const double lam = (j + 0.5) * 2.0 * pi / n_lon;
      const Vec3 centre(r * std::cos(bm) * std::cos(lam), r * std::cos(bm) * std::sin(lam), r * std::sin(bm));
      add_patch(t, part, sp, centre, centre.normalized(), band / n_lon);
    }
    off += n_lon;
    grid.push_back(off);
  }
  // The cone's side from the tangent circle (rb) to the apex (rt = 0).
  const double rb = pp.tangent_radius_m, len = pp.apex_z_m - pp.tangent_z_m;
  const double slant = std::hypot(rb, len);
  const double side = pi * rb * slant;
  const int n_h = count_for(slant, target);
  const int n_a = static_cast<int>(std::max(8.0, std::round(side / (n_h * target * target))));
  grid.insert(grid.end(), {n_a, n_h, off});
  for (int i = 0; i < n_h; ++i) {
    const double w = frustum_w(rb, 0.0, (i + 0.5) / n_h);
    const double z = pp.tangent_z_m + w * len, rr = rb * (1.0 - w);
    for (int j = 0; j < n_a; ++j) {
      const double phi = (j + 0.5) * 2.0 * pi / n_a;
      const Vec3 c(rr * std::cos(phi), rr * std::sin(phi), z);
      add_patch(t, part, sp, c, Vec3(std::cos(phi), std::sin(phi), rb / len).normalized(), side / (n_h * n_a));
    }
  }
}

std::int32_t plume_cell(const std::vector<std::int32_t>& grid, const ShapeGeom& g, const Vec3& p) {
  const PlumeProfile pp = plume_profile(g);
  const int n_lat = grid[0];
  if (p.z() <= pp.tangent_z_m) {
    const double r = g.a_m;
    const double beta_t = std::asin(std::clamp(pp.tangent_z_m / r, -1.0, 1.0));
    const double beta = std::atan2(p.z(), std::hypot(p.x(), p.y()));
    const int i = clamp_index((beta + 0.5 * pi) / ((beta_t + 0.5 * pi) / n_lat), n_lat);
    const int n_lon = grid[1 + i + 1] - grid[1 + i];
    return grid[1 + i] + clamp_index(azimuth(p.x(), p.y()) / (2.0 * pi / n_lon), n_lon);
  }
  const std::size_t c = static_cast<std::size_t>(n_lat) + 2;
  const int n_a = grid[c], n_h = grid[c + 1], off = grid[c + 2];
  const double len = pp.apex_z_m - pp.tangent_z_m;
  const double w = std::clamp((p.z() - pp.tangent_z_m) / len, 0.0, 1.0);
  const int i = clamp_index(frustum_f(pp.tangent_radius_m, 0.0, w) * n_h, n_h);
  return off + i * n_a + clamp_index(azimuth(p.x(), p.y()) / (2.0 * pi / n_a), n_a);
}

std::int32_t spheroid_cell(const std::vector<std::int32_t>& grid, const ShapeGeom& g, const Vec3& p) {
  const int n_lat = grid[0];
  const double beta = std::atan2(p.z() / g.c_m, std::sqrt(p.x() * p.x() + p.y() * p.y()) / g.a_m);
  const int i = clamp_index((beta + 0.5 * pi) / (pi / n_lat), n_lat);
  const int n_lon = grid[1 + i + 1] - grid[1 + i];
  const int j = clamp_index(azimuth(p.x(), p.y()) / (2.0 * pi / n_lon), n_lon);
  return grid[1 + i] + j;
}

std::int32_t face_cell(const std::vector<std::int32_t>& grid, int face, int axis, const Vec3& half, const Vec3& p) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int nu = grid[3 * face], nv = grid[3 * face + 1];
  const int iu = clamp_index((p[u] + half[u]) / (2 * half[u]) * nu, nu);
  const int iv = clamp_index((p[v] + half[v]) / (2 * half[v]) * nv, nv);
  return grid[3 * face + 2] + iv * nu + iu;
}

std::int32_t frustum_cell(const std::vector<std::int32_t>& grid, const ShapeGeom& g, const Vec3& p) {
  const int face = frustum_face(g, p);
  const int n_a = grid[3 * face], n_r = grid[3 * face + 1], off = grid[3 * face + 2];
  const int j = clamp_index(azimuth(p.x(), p.y()) / (2.0 * pi / n_a), n_a);
  int i = 0;
  if (face == 0) {
    const double w = std::clamp((p.z() + 0.5 * g.length_m) / g.length_m, 0.0, 1.0);
    i = clamp_index(frustum_f(g.r_bottom_m, g.r_top_m, w) * n_r, n_r);
  } else {
    const double radius = face == 1 ? g.r_bottom_m : g.r_top_m;
    i = clamp_index((p.x() * p.x() + p.y() * p.y()) / (radius * radius) * n_r, n_r);
  }
  return off + i * n_a + j;
}

void tessellate_mesh(Tessellation& t, std::int32_t part, const ShapePart& sp, const ShapeGeom& g,
                     std::vector<std::int32_t>& grid) {
  std::int32_t off = 0;
  for (std::int32_t tri : g.mesh->group_triangles(g.mesh_group)) {
    grid.push_back(off);
    const Vec3& n = g.mesh->normal(tri);
    add_patch(t, part, sp, g.mesh->centroid_m(tri), n, g.mesh->area_m2(tri));
    ++off;
    if (!g.mesh->one_sided(tri)) {
      add_patch(t, part, sp, g.mesh->centroid_m(tri), -n, g.mesh->area_m2(tri));
      ++off;
    }
  }
}

// The patch of a mesh part at p: its nearest triangle's, the face of an open
// sheet picked by the seen side's normal.
std::int32_t mesh_cell(const std::vector<std::int32_t>& grid, const ShapeGeom& g, const Vec3& p, const Vec3& normal_part) {
  const std::int32_t tri = g.mesh->nearest_triangle(g.mesh_group, p);
  const auto& triangles = g.mesh->group_triangles(g.mesh_group);
  const auto at = std::lower_bound(triangles.begin(), triangles.end(), tri);
  const std::int32_t local = grid[static_cast<std::size_t>(at - triangles.begin())];
  return local + (!g.mesh->one_sided(tri) && normal_part.dot(g.mesh->normal(tri)) < 0 ? 1 : 0);
}

}  // namespace

Tessellation tessellate(const std::vector<ShapePart>& parts, double target_patch_size_m) {
  require_positive(target_patch_size_m, "patch_size_m");
  Tessellation t;
  t.target_patch_size_m = target_patch_size_m;
  t.grid.resize(parts.size());
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const auto part = static_cast<std::int32_t>(k);
    const ShapeGeom& g = parts[k].geom;
    const double estimate = shape_surface_area_m2(g) / (target_patch_size_m * target_patch_size_m);
    if (g.kind != ShapeKind::mesh && !(estimate <= kMaxPatchesPerPart)) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "patch_size_m: a patch edge of %g m gives about %.3g patches on part %zu, at most %.0e: raise "
                    "patch_size_m (or the sensor's central_body_patch_size_m / object_patch_divisions)",
                    target_patch_size_m, estimate, k, kMaxPatchesPerPart);
      throw Error(Status::limit_exceeded, text);
    }
    t.first_patch.push_back(static_cast<std::int32_t>(t.patches.size()));
    auto& grid = t.grid[k];
    const double target = target_patch_size_m;
    switch (g.kind) {
      case ShapeKind::sphere:
      case ShapeKind::oblate: tessellate_spheroid(t, part, parts[k], g, target, grid); break;
      case ShapeKind::box: {
        const Vec3 half(0.5 * g.x_m, 0.5 * g.y_m, 0.5 * g.z_m);
        std::int32_t off = 0;
        for (int f = 0; f < 6; ++f)
          tessellate_face(t, part, parts[k], half, f / 2, f % 2 ? -1.0 : 1.0, target, grid, off);
        break;
      }
      case ShapeKind::plate: {
        const Vec3 half(0.5 * g.x_m, 0.5 * g.y_m, 0.0);
        std::int32_t off = 0;
        tessellate_face(t, part, parts[k], half, 2, 1.0, target, grid, off);
        tessellate_face(t, part, parts[k], half, 2, -1.0, target, grid, off);
        break;
      }
      case ShapeKind::cylinder:
      case ShapeKind::cone:
      case ShapeKind::coupler: tessellate_frustum(t, part, parts[k], g, target, grid); break;
      case ShapeKind::mesh: tessellate_mesh(t, part, parts[k], g, grid); break;
      case ShapeKind::plume: tessellate_plume(t, part, parts[k], g, target, grid); break;
      case ShapeKind::none:
      case ShapeKind::composite: break;
    }
  }
  return t;
}

std::int32_t patch_in_part(const Tessellation& t, std::int32_t part, const ShapeGeom& g, const Vec3& p,
                           const Vec3& normal_part) {
  if (part < 0 || static_cast<std::size_t>(part) >= t.grid.size()) return -1;
  const auto& grid = t.grid[static_cast<std::size_t>(part)];
  if (grid.empty()) return -1;
  std::int32_t local = -1;
  switch (g.kind) {
    case ShapeKind::sphere:
    case ShapeKind::oblate: local = spheroid_cell(grid, g, p); break;
    case ShapeKind::box: {
      const int face = box_face(g, p);
      local = face_cell(grid, face, face / 2, Vec3(0.5 * g.x_m, 0.5 * g.y_m, 0.5 * g.z_m), p);
      break;
    }
    case ShapeKind::plate:
      local = face_cell(grid, normal_part.z() < 0 ? 1 : 0, 2, Vec3(0.5 * g.x_m, 0.5 * g.y_m, 0.0), p);
      break;
    case ShapeKind::cylinder:
    case ShapeKind::cone:
    case ShapeKind::coupler: local = frustum_cell(grid, g, p); break;
    case ShapeKind::mesh: local = mesh_cell(grid, g, p, normal_part); break;
    case ShapeKind::plume: local = plume_cell(grid, g, p); break;
    case ShapeKind::none:
    case ShapeKind::composite: return -1;
  }
  return t.first_patch[static_cast<std::size_t>(part)] + local;
}

std::int32_t patch_at_facet(const Tessellation& t, const std::vector<ShapePart>& parts, std::int32_t part,
                            std::int32_t facet, const Vec3& point_body_m, const Vec3& normal_body) {
  if (facet < 0 || part < 0 || static_cast<std::size_t>(part) >= parts.size())
    return patch_at_facing(t, parts, part, point_body_m, normal_body);
  const ShapePart& sp = parts[static_cast<std::size_t>(part)];
  const auto& grid = t.grid[static_cast<std::size_t>(part)];
  const std::int32_t tri = sp.geom.mesh->group_triangles(sp.geom.mesh_group)[static_cast<std::size_t>(facet)];
  const bool back = !sp.geom.mesh->one_sided(tri) &&
                    (sp.orientation.conjugate() * normal_body).dot(sp.geom.mesh->normal(tri)) < 0;
  return t.first_patch[static_cast<std::size_t>(part)] + grid[static_cast<std::size_t>(facet)] + (back ? 1 : 0);
}

std::int32_t patch_at_facing(const Tessellation& t, const std::vector<ShapePart>& parts, std::int32_t part,
                             const Vec3& point_body_m, const Vec3& normal_body) {
  if (part < 0 || static_cast<std::size_t>(part) >= parts.size()) return -1;
  const ShapePart& sp = parts[static_cast<std::size_t>(part)];
  const Mat3 r = sp.orientation.toRotationMatrix();
  return patch_in_part(t, part, sp.geom, r.transpose() * (point_body_m - sp.offset_m),
                       r.transpose() * normal_body);
}

}  // namespace eoir::geometry
