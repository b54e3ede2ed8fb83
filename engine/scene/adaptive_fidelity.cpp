#include "scene/adaptive_fidelity.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/constants.hpp"
#include "radiometry/band_integral.hpp"

namespace eoir::scene {
namespace {

// The Sun's effective temperature (IAU 2015 B3): the Planck continuum that
// stands for reflected sunlight and for stars of solar colour.
constexpr double sun_effective_temperature_K = 5772.0;
// Stellar continua from M to B stars: stars are m0 B(T) (spec 4.1.6.1).
constexpr double coolest_star_K = 3000.0, hottest_star_K = 30000.0;
// At most this many probe rays per axis (one per pixel centre, strided).
constexpr std::int64_t probe_rays_per_axis = 128;
// Coarse patch errors are estimated on at most this many probe points.
constexpr std::size_t patch_probe_points = 2048;
// Coarse patches are tried from the sensor's edge down to this fraction of it
// (each halving quadruples the patches; smooth mode beyond).
constexpr double smallest_patch_fraction = 1.0 / 16.0;
// The detailed point-source sum converges toward its value at this many divisions.
constexpr double finest_object_patch_divisions = 128.0;

// Relative error of the band-integral rule with N intervals on B_lambda(T)
// (spec 5.3, eq. 48) against the exact series integral.
double planck_rule_error(double T, const radiometry::SpectralBand& band, std::int64_t intervals,
                         SpectralQuadrature rule) {
  const double exact = radiometry::planck_band_radiance(T, band.low_um, band.high_um);
  if (!(exact > 0)) return 0;
  const radiometry::SpectralBand b{band.low_um, band.high_um, intervals};
  return std::abs(radiometry::grid_planck_band_radiance(T, b, rule) - exact) / exact;
}

// A Planck continuum of the frame and its weight: its in-band radiance
// against the largest of the frame's (sunlight as reflected by a white
// Lambertian surface at 1 au: B(T_sun) Omega_sun / pi), or 1 for stars
// (each its own source).
struct PlanckTerm {
  double temperature_K = 0, weight = 1;
};

// Temperatures whose Planck spectra the grid integrates in this frame.
std::vector<PlanckTerm> planck_terms(const World& world, const universe::Universe& universe) {
  std::vector<double> out;
  const bool exact = world.fidelity().band_integration == BandIntegration::exact;  // emission off the grid
  bool reflected = false;
  for (const auto& o : world.objects) {
    if (o->imaging == Imaging::outside || !o->surface) continue;
    reflected = reflected || o->surface->reflects();
    if (exact) continue;
    const universe::Object* u = universe.find(o->name);
    if (!u) continue;
    out.push_back(u->body.temperature_K);
    for (const universe::ShapePart& p : universe::shape_parts_at(*u, world.time))
      if (p.temperature_K) out.push_back(*p.temperature_K);
  }
  const radiometry::SpectralBand& band = world.spectral().band;
  const auto in_band = [&](double T) { return radiometry::planck_band_radiance(T, band.low_um, band.high_um); };
  constexpr double sun_solid_angle_at_1au_sr = 6.8e-5;
  double largest = reflected ? in_band(sun_effective_temperature_K) * sun_solid_angle_at_1au_sr / constants::pi : 0.0;
  for (double T : out) largest = std::max(largest, in_band(T));
  std::vector<PlanckTerm> terms;
  for (double T : out) terms.push_back({T, largest > 0 ? in_band(T) / largest : 0.0});
  if (reflected) terms.push_back({sun_effective_temperature_K, 1.0});
  if (!world.sky.stars.empty()) {
    terms.push_back({coolest_star_K, 1.0});
    terms.push_back({hottest_star_K, 1.0});
  }
  return terms;
}

// The smallest N >= `intervals` whose rule error is within `share` at every
// temperature (the sensor's N resolves what the model cannot bound: material
// spectra), and that error.
std::int64_t spectral_intervals_for(const World& world, const std::vector<PlanckTerm>& terms,
                                    std::int64_t intervals, double share, double& error) {
  const radiometry::SpectralBand& band = world.spectral().band;
  const SpectralQuadrature rule = world.fidelity().spectral_quadrature;
  const auto worst = [&](std::int64_t n) {
    double e = 0;
    for (const PlanckTerm& t : terms)
      if (t.weight > 0) e = std::max(e, t.weight * planck_rule_error(t.temperature_K, band, n, rule));
    return e;
  };
  std::int64_t n = intervals;
  error = worst(n);
  while (error > share && n < 100000) {
    n = std::min<std::int64_t>(100000, std::max(n + 1, n * 5 / 4));
    error = worst(n);
  }
  return n;
}

struct ProbeSample {
  std::int32_t object = -1, part = -1;
  double radiance = 0;              // smooth (the sample's own point), W cm^-2 sr^-1
  Vec3 point_body_m = Vec3::Zero();
  Vec3 normal_body = Vec3::UnitZ();
  bool coarse_surface = false;      // on a central body whose radiance varies (coarse patches apply)
};

// One ray per pixel centre (strided to at most probe_rays_per_axis per axis)
// against the objects imaged extended.
std::vector<ProbeSample> probe_field(const World& world, std::int64_t& stride, std::int64_t& columns, unsigned threads) {
  const geometry::SampleGrid& g = world.grid();
  stride = std::max<std::int64_t>(1, (std::max(g.pixels_x, g.pixels_y) + probe_rays_per_axis - 1) / probe_rays_per_axis);
  columns = (g.pixels_x + stride - 1) / stride;
  const std::int64_t rows = (g.pixels_y + stride - 1) / stride;
  std::vector<Vec3> directions;
  directions.reserve(static_cast<std::size_t>(columns * rows));
  for (std::int64_t r = 0; r < rows; ++r)
    for (std::int64_t c = 0; c < columns; ++c)
      directions.push_back(world.sample_direction(g.guard_samples() + (c * stride) * g.per_pixel + g.per_pixel / 2,
                                                  g.guard_samples() + (r * stride) * g.per_pixel + g.per_pixel / 2));
  std::vector<geometry::Hit> hits;
  world.caster.cast(directions, hits, threads, geometry::RayQuery{geometry::ray_mask_extended, -1});
  std::vector<ProbeSample> out(hits.size());
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const geometry::Hit& h = hits[i];
    ProbeSample& s = out[i];
    s.object = h.object_id;
    s.part = h.part;
    if (h.object_id < 0) continue;
    const WorldObject& o = *world.objects[static_cast<std::size_t>(h.object_id)];
    const Vec3 normal = o.direction_to_body(h.normal_frame);
    s.radiance = o.effective_radiance(h.part, h.point_body_m, normal);
    s.point_body_m = h.point_body_m;
    s.normal_body = normal;
    s.coarse_surface = o.central_body && !o.surface->plain();
  }
  return out;
}

// The atmosphere's table knobs (core/fidelity.hpp): each one's error at its
// default (relative RMS of the pixel means against tables at the sweep's
// reference settings, the largest over the sweep's atmosphere scenes:
// tests/bench/results/fidelity_sweep.md), and the range the choice keeps
// to. Linear interpolation between nodes errs as h^2.
struct AtmosphereNodes {
  std::int64_t Fidelity::*knob;
  std::int64_t default_nodes;
  double default_error;
  std::int64_t fewest, most;
};
// (The sweep: GEO full disc in 0.45-0.75 and 8-12 um, a ground camera's
// daytime sky; each knob halving its node spacing cut its error about 4x.)
constexpr AtmosphereNodes kAtmosphereNodes[] = {
    {&Fidelity::atmosphere_surface_nodes, 33, 3.73e-4, 5, 257},     // GEO visible
    {&Fidelity::atmosphere_sight_line_nodes, 33, 1.09e-3, 5, 257},  // ground sky
    {&Fidelity::atmosphere_sky_azimuths, 49, 3.53e-4, 7, 385},      // ground sky
    {&Fidelity::atmosphere_sun_nodes, 33, 1.39e-4, 5, 257},         // ground sky
    {&Fidelity::atmosphere_downwelling_nodes, 40, 1.24e-5, 5, 320}, // GEO visible
};
// The transmittance's sub-sample spacing: past the band models' 20 cm^-1
// resolution the error jumps (their structure is missed), so the sweep's
// errors at its values are the model, coarsest first.
struct SpacingError {
  double spacing_cm1, error;
};
constexpr SpacingError kSpacingErrors[] = {{80.0, 2.42e-3}, {40.0, 1.61e-3}, {20.0, 3.18e-4}, {10.0, 4.05e-5}};  // GEO 8-12 um

// Chooses the atmosphere's knobs the frame reads (world.atmosphere's tables)
// within `share`, summed over them (not in quadrature: their errors can
// share a sign -- the same haze brighter from two tables -- and on the
// sweep's GEO disc the frame's error exceeded their quadrature sum); returns
// that sum.
double choose_atmosphere(const World& world, double share, Fidelity& f) {
  const WorldAtmosphere& a = world.atmosphere;
  if (!a.on()) return 0.0;
  // The knobs this frame reads: the sub-samples always; the surface's paths
  // where the Earth is imaged; the sky's lines and azimuths and T_sun in
  // sunlight; DownWelling where it is on.
  const bool reads[] = {a.surface != nullptr, a.sky != nullptr, a.sky != nullptr, a.sunlight != nullptr,
                        a.downwelling != nullptr};
  int count = 1;
  for (const bool r : reads) count += r ? 1 : 0;
  const double each = share / static_cast<double>(count);
  double sum = 0;
  std::size_t k = 0;
  for (const AtmosphereNodes& knob : kAtmosphereNodes) {
    if (!reads[k++]) continue;
    const auto error = [&](std::int64_t n) {
      const double r = static_cast<double>(knob.default_nodes - 1) / static_cast<double>(n - 1);
      return knob.default_error * r * r;
    };
    // Node counts (n0 - 1) 2^j + 1 (rounded), j = -3..3, coarsest first.
    std::int64_t n = knob.most;
    for (int j = -3; j <= 3; ++j) {
      const auto m = std::clamp<std::int64_t>(
          std::llround(static_cast<double>(knob.default_nodes - 1) * std::ldexp(1.0, j)) + 1, knob.fewest, knob.most);
      if (error(m) <= each) {
        n = m;
        break;
      }
    }
    f.*knob.knob = n;
    sum += error(n);
  }
  const SpacingError* s = &kSpacingErrors[std::size(kSpacingErrors) - 1];
  for (const SpacingError& x : kSpacingErrors)
    if (x.error <= each) {
      s = &x;
      break;
    }
  f.atmosphere_sub_sample_spacing_cm1 = s->spacing_cm1;
  // Every level of the profile: a coarser one (atmosphere_layer_stride)
  // only shortens the making of the tables, once per atmosphere and band,
  // never a frame (the sweep's errors for it are in fidelity_sweep.md).
  f.atmosphere_layer_stride = 1;
  return sum + s->error;
}

// Coverage error of n x n samples on an edge pixel, RMS, in units of the
// contrast: each sample row quantises the covered length to 1 / n of the
// pixel, a uniform error of RMS 1 / (n sqrt 12); rows parallel to the edge
// err together (the worst case).
double edge_coverage_rms(std::int64_t n) { return 1.0 / (static_cast<double>(n) * std::sqrt(12.0)); }

}  // namespace

double FidelityChoice::estimated_error() const {
  return std::sqrt(spectral_error * spectral_error + sampling_error * sampling_error + patch_error * patch_error +
                   point_source_error * point_source_error + atmosphere_error * atmosphere_error);
}

std::string FidelityChoice::json() const {
  nlohmann::ordered_json j;
  j["error_budget"] = error_budget;
  j["estimated_error"] = estimated_error();
  j["spectral_error"] = spectral_error;
  j["sampling_error"] = sampling_error;
  j["patch_error"] = patch_error;
  j["point_source_error"] = point_source_error;
  j["atmosphere_error"] = atmosphere_error;
  j["spectral_intervals"] = spectral_intervals;
  for (const PropertySpec<Fidelity>& k : fidelity_properties()) {
    if (std::string(k.name) == "error_budget") continue;
    std::visit([&](const auto& v) { j[k.name] = v; }, k.get(fidelity));
  }
  return j.dump();
}

FidelityChoice fixed_fidelity(const Fidelity& fidelity, std::int64_t spectral_intervals) {
  FidelityChoice c;
  c.fidelity = fidelity;
  c.spectral_intervals = spectral_intervals;
  c.error_budget = fidelity.error_budget;
  return c;
}

FidelityChoice choose_fidelity(const World& world, const universe::Universe& universe,
                               std::int64_t spectral_intervals, unsigned threads) {
  const Fidelity& own = world.fidelity();
  FidelityChoice c = fixed_fidelity(own, spectral_intervals);
  if (!(own.error_budget > 0)) return c;
  const double budget = own.error_budget;
  // Knobs that cost little to tighten get a tenth of the budget each; the
  // scene grid (samples per pixel, scene mode), whose cost grows as n^2, the rest.
  const double cheap_share = 0.1 * budget;
  Fidelity& f = c.fidelity;

  // Spectral intervals (spec 5.3, eq. 48).
  c.spectral_intervals =
      spectral_intervals_for(world, planck_terms(world, universe), spectral_intervals, cheap_share, c.spectral_error);

  // The atmosphere's tables (issue 20 item 8).
  c.atmosphere_error = choose_atmosphere(world, cheap_share, f);

  // Detailed point sources (spec 4.1.6.1, ERRATA eq. 11): d against the finest d;
  // where none is within the share, the finest and its distance to the one before.
  bool composite_points = false;
  double divisions = 2.0;
  for (const auto& o : world.objects) {
    if (o->imaging == Imaging::extended && !o->central_body && !o->surface->plain())
      divisions = std::max(divisions, own.object_patch_divisions);  // its coarse patches stay as fine
    // (small extended objects are imaged from the same sum: scene/scene_generator.cpp)
    if ((o->imaging != Imaging::point_source && o->imaging != Imaging::small_extended) ||
        !o->detailed_point_source || o->central_body)
      continue;
    if (o->placed.parts.size() == 1 && o->surface->plain()) continue;  // exact (analytic projected area)
    const universe::Object* u = universe.find(o->name);
    if (!u || u->body.patch_size_m > 0) continue;  // the object's own patch edge
    composite_points = true;
    const double size_m = o->patch_size_m * own.object_patch_divisions;  // its largest part's diameter
    // Against the finest sum: consecutive sums of parts that shade each
    // other can agree by chance far from the limit.
    const double finest = o->detailed_point_irradiance_W_cm2(size_m / finest_object_patch_divisions);
    double d = 2.0, e = 0;
    for (; d < finest_object_patch_divisions; d *= 2.0) {
      e = finest > 0 ? std::abs(o->detailed_point_irradiance_W_cm2(size_m / d) - finest) / finest : 0.0;
      if (e <= cheap_share) break;
    }
    divisions = std::max(divisions, d);
    c.point_source_error = std::max(c.point_source_error, e);
  }
  if (composite_points) f.object_patch_divisions = divisions;

  // Samples per pixel (spec 4.1.3, 5.2) and coarse patches (4.2.1) or smooth
  // mode (4.2.2): the cheapest pair within what the budget leaves.
  const double spent2 = c.spectral_error * c.spectral_error + c.point_source_error * c.point_source_error +
                        c.atmosphere_error * c.atmosphere_error;
  const geometry::SampleGrid& g = world.grid();
  bool extended = false;
  std::int64_t fewest = 1;  // keeps every object imaged extended so (spec 4.1.6.1)
  for (const auto& o : world.objects) {
    if (o->imaging != Imaging::extended) continue;
    extended = true;
    if (o->range_m > o->bounding_radius_m) {
      const double angle = 2.0 * std::asin(o->bounding_radius_m / o->range_m);
      const double pixel_angle = g.sample_angle_rad() * static_cast<double>(g.per_pixel);
      fewest = std::max<std::int64_t>(fewest, static_cast<std::int64_t>(std::ceil(pixel_angle / angle)));
    }
  }
  fewest = std::min<std::int64_t>(fewest, 16);
  if (!extended) {
    f.samples_per_pixel = 1;  // point sources and the sky: no edge to sample
    f.edge_supersampling = 1;
    return c;
  }
  std::int64_t stride = 1, columns = 1;
  const std::vector<ProbeSample> probe = probe_field(world, stride, columns, threads);
  double sum_L2 = 0, sum_edge2 = 0, crossings = 0;
  for (std::size_t i = 0; i < probe.size(); ++i) {
    const ProbeSample& s = probe[i];
    sum_L2 += s.radiance * s.radiance;
    const auto edge = [&](std::size_t j) {
      if (probe[j].object != s.object || probe[j].part != s.part) {
        const double dL = probe[j].radiance - s.radiance;
        sum_edge2 += dL * dL;
        crossings += 1;
      }
    };
    const auto column = static_cast<std::int64_t>(i) % columns;
    if (column + 1 < columns) edge(i + 1);
    if (i + static_cast<std::size_t>(columns) < probe.size()) edge(i + static_cast<std::size_t>(columns));
  }
  if (!(sum_L2 > 0)) {
    f.samples_per_pixel = fewest;
    f.edge_supersampling = 1;
    return c;
  }
  // Each probe link crossing an edge stands for `stride` edge pixels among stride^2 pixels per probe.
  const double edge_fraction = sum_edge2 / (static_cast<double>(stride) * sum_L2);
  const double edge_pixels = std::min(1.0, crossings / (static_cast<double>(stride) * static_cast<double>(probe.size())));
  // n x n samples with s x s sub-samples at silhouette edges cover an edge
  // pixel as (n s)^2 samples do (scene/scene_generator.cpp).
  const auto sampling_error = [&](std::int64_t n, std::int64_t s) {
    return edge_coverage_rms(n * s) * std::sqrt(edge_fraction);
  };
  // Coarse-mode error of patches of edge s on central bodies (spec 4.2.1): a
  // sample takes the radiance of its patch centre, offset from it by u, v
  // uniform in [-s/2, s/2] along the surface. To first order the mean square
  // error is (g_u^2 + g_v^2) s^2 / 12; taking the differences to the points
  // s/2 away along both tangents (over 3, the same to first order) also sees
  // what varies faster than the patch (sun glint, the horizon).
  std::vector<std::size_t> on_bodies;
  for (std::size_t i = 0; i < probe.size(); ++i)
    if (probe[i].coarse_surface) on_bodies.push_back(i);
  const std::size_t every = std::max<std::size_t>(1, on_bodies.size() / patch_probe_points);
  const auto patch_error = [&](double s) {
    double e2 = 0;
    std::size_t used = 0;
    for (std::size_t k = 0; k < on_bodies.size(); k += every, ++used) {
      const ProbeSample& p = probe[on_bodies[k]];
      const WorldObject& o = *world.objects[static_cast<std::size_t>(p.object)];
      const Vec3 t1 = p.normal_body.unitOrthogonal(), t2 = p.normal_body.cross(t1);
      for (const Vec3& t : {Vec3(t1), Vec3(-t1), Vec3(t2), Vec3(-t2)}) {
        Vec3 q = p.point_body_m + 0.5 * s * t;
        q *= p.point_body_m.norm() / q.norm();  // back to the surface, radially
        const double dL = o.effective_radiance(p.part, q, o.normal_at(p.part, q)) - p.radiance;
        e2 += dL * dL / (2.0 * 3.0);  // two tangents averaged over two signs each, over 3
      }
    }
    // The body's share of the frame: its probes' mean square error times their count.
    return used ? std::sqrt(e2 / static_cast<double>(used) * static_cast<double>(on_bodies.size()) / sum_L2) : 0.0;
  };
  // Relative cost of a frame per pixel: n^2 samples plus s^2 sub-samples on
  // each sample at an edge (about 3 n per edge pixel: the samples an edge
  // crosses and their neighbours across it), shaded each in smooth mode at
  // about 1.3 times a coarse sample's cost (tests/bench/results/fidelity_sweep.md).
  constexpr double smooth_cost_factor = 1.3;
  double best_cost = std::numeric_limits<double>::infinity();
  const auto consider = [&](SceneMode mode, double patch_m, double e_patch) {
    const double left2 = budget * budget - spent2 - e_patch * e_patch;
    if (left2 <= 0) return;
    for (std::int64_t n = fewest; n <= 16; ++n)
      for (std::int64_t s = 1; s <= 16; ++s) {
        if (sampling_error(n, s) > std::sqrt(left2)) continue;
        const auto N = static_cast<double>(n), S = static_cast<double>(s);
        const double cost = (N * N + (s > 1 ? 3.0 * N * edge_pixels * S * S : 0.0)) *
                            (mode == SceneMode::coarse ? 1.0 : smooth_cost_factor);
        if (cost < best_cost) {
          best_cost = cost;
          f.scene_mode = mode;
          f.central_body_patch_size_m = patch_m;
          f.samples_per_pixel = n;
          f.edge_supersampling = s;
          c.patch_error = e_patch;
          c.sampling_error = sampling_error(n, s);
        }
        break;  // more sub-samples only cost more
      }
  };
  if (own.scene_mode == SceneMode::bitmap) {  // the surface map's materials: a model of its own, kept
    consider(SceneMode::bitmap, own.central_body_patch_size_m, 0.0);
  } else {
    for (double s = own.central_body_patch_size_m; s >= own.central_body_patch_size_m * smallest_patch_fraction;
         s *= 0.5)
      consider(SceneMode::coarse, s, patch_error(s));
    consider(SceneMode::smooth, own.central_body_patch_size_m, 0.0);
  }
  if (!std::isfinite(best_cost)) {  // beyond the model's reach: the finest settings it knows
    f.scene_mode = own.scene_mode == SceneMode::bitmap ? SceneMode::bitmap : SceneMode::smooth;
    f.samples_per_pixel = 16;
    f.edge_supersampling = 16;
    c.patch_error = 0;
    c.sampling_error = sampling_error(16, 16);
  }
  return c;
}

}  // namespace eoir::scene
