#include "scene/world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

#include "atmosphere/aerosol_optics.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/frames.hpp"
#include "geometry/part_shadow.hpp"
#include "geometry/projected_area.hpp"
#include "scene/cloud_top.hpp"
#include "universe/object_motion.hpp"
#include "universe/rotation_models.hpp"

namespace eoir::scene {
namespace {
using universe::ObjectKind;

// Relative size below which a term of a sample's radiance is left out: its
// self-emission beside its reflected light (WorldObject::effective_radiance),
// an eq. 7 source's light beside its self-emission (build_world).
constexpr double kNegligible = 1e-10;
// A source's eq. 7 light at a point is left out where it cannot reach this
// fraction of the irradiance the point already has at any wavelength (all
// terms are non-negative, so the band radiance moves by less than this
// fraction per source left out).
constexpr double kNegligibleAtPoint = 1e-12;

// A light's disc, pi R^2 (m^2).
double disc_area_m2(const ObjectLight& src) { return constants::pi * src.radius_m * src.radius_m; }

// At squared distance distance2_m2 a light is its disc (eq. 7) unless an
// area source subtending half area_source_solid_angle_sr or more there
// (eq. 8's tessellation, or its disc near the threshold).
bool seen_as_disc(const ObjectLight& src, double distance2_m2, const Fidelity& fidelity) {
  return !src.area_source || disc_area_m2(src) < 0.5 * fidelity.area_source_solid_angle_sr * distance2_m2;
}

// The disc's light through a BRDF whose N.L value is at most brdf_max_per_sr,
// dOmega x brdf_max x its band bound, below negligible_W_cm2_sr (compared
// times the squared distance: no division for a light left out).
bool disc_light_below(const ObjectLight& src, double distance2_m2, double brdf_max_per_sr, const LightSpectra& spectra,
                      double negligible_W_cm2_sr) {
  return disc_area_m2(src) * brdf_max_per_sr * spectra.bound_band_W_cm2_sr < negligible_W_cm2_sr * distance2_m2;
}

// True if a sphere (centre in sensor body axes, radius) lies wholly outside
// the pyramid of the sample grid (field of view plus guard band).
bool outside_view(const Vec3& centre_body, double radius, const geometry::SampleGrid& grid) {
  if (centre_body.norm() <= radius) return false;  // around the sensor: let the ray caster decide
  const double tx = std::fabs(grid.tan_x(0)), ty = std::fabs(grid.tan_y(0));
  // Outward unit normals of the four side planes of the pyramid.
  const Vec3 planes[4] = {Vec3(1, 0, -tx).normalized(), Vec3(-1, 0, -tx).normalized(), Vec3(0, 1, -ty).normalized(),
                          Vec3(0, -1, -ty).normalized()};
  for (const Vec3& n : planes)
    if (n.dot(centre_body) > radius) return true;
  return false;
}

// Default patch edge (spec 4.1.5.2, 4.2.3) from the sensor's fidelity.
double patch_size_m(const universe::Object& o, const std::vector<geometry::ShapePart>& parts, const Fidelity& f) {
  if (o.body.patch_size_m > 0) return o.body.patch_size_m;
  if (o.kind == ObjectKind::central_body)
    return f.central_body_patch_size_m * o.body.dimensions_m[0] / 6378137.0;  // scaled from the Earth's radius
  if (o.kind == ObjectKind::missile && !o.body.missile_stage_list->empty()) {
    // A missile's stages and plumes are long and thin: patches from its
    // narrowest stage's diameter, not its length (or its plume's).
    double narrowest = std::numeric_limits<double>::infinity();
    for (const universe::MissileStage& s : *o.body.missile_stage_list) narrowest = std::min(narrowest, s.radius_m);
    return 2.0 * narrowest / f.object_patch_divisions;
  }
  double size = 0;
  for (const auto& part : parts) size = std::max(size, 2.0 * geometry::shape_bounding_radius_m(part.geom));
  return std::max(size, 1e-6) / f.object_patch_divisions;
}

// Volume of a simple shape (m^3); a plate has none.
double shape_volume_m3(const geometry::ShapeGeom& g) {
  const double pi = constants::pi;
  switch (g.kind) {
    case universe::ShapeKind::sphere:
    case universe::ShapeKind::oblate: return 4.0 / 3.0 * pi * g.a_m * g.a_m * g.c_m;
    case universe::ShapeKind::box: return g.x_m * g.y_m * g.z_m;
    case universe::ShapeKind::cylinder:
    case universe::ShapeKind::cone:
    case universe::ShapeKind::coupler: {
      const double r1 = g.r_bottom_m, r2 = g.r_top_m;
      return pi * g.length_m * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0;
    }
    case universe::ShapeKind::mesh: return g.mesh->volume_m3(g.mesh_group);  // (its closed pieces')
    case universe::ShapeKind::plume: {  // the sphere less its cap above the tangent circle, plus the cone
      const geometry::PlumeProfile p = geometry::plume_profile(g);
      const double r = g.a_m, cap = r - p.tangent_z_m;
      return 4.0 / 3.0 * pi * r * r * r - pi * cap * cap * (3.0 * r - cap) / 3.0 +
             pi * p.tangent_radius_m * p.tangent_radius_m * (p.apex_z_m - p.tangent_z_m) / 3.0;
    }
    default: return 0.0;
  }
}

// Eq. 7's sphere of the object's true shape: its volumetric mean radius; for
// objects without volume (plates) the sphere of equal surface area.
double volumetric_radius_m(const std::vector<geometry::ShapePart>& parts) {
  double volume = 0, area = 0;
  for (const auto& p : parts) {
    volume += shape_volume_m3(p.geom);
    area += geometry::shape_surface_area_m2(p.geom);
  }
  if (volume > 0) return std::cbrt(3.0 * volume / (4.0 * constants::pi));
  return std::sqrt(area / (4.0 * constants::pi));
}

// Whether an occulter can shade any point of a receiving sphere from a light
// sphere: it must cross the cone that joins them (a conservative test that
// keeps the per-point eclipse tests short).
bool can_shade(const Vec3& receiver, double receiver_radius, const Vec3& light, double light_radius,
               const geometry::Occulter& o) {
  const double r_o = std::max(o.equatorial_radius_m, o.polar_radius_m);
  const Vec3 to_light = light - receiver;
  const double D = to_light.norm();
  if (!(D > 0)) return false;
  const Vec3 u = to_light / D;
  const Vec3 rel = o.centre_m - receiver;
  const double s = rel.dot(u);
  if (s < -(r_o + receiver_radius) || s > D + r_o) return false;
  const double h = (rel - s * u).norm();
  const double cone = receiver_radius + std::max(0.0, light_radius - receiver_radius) * std::clamp(s / D, 0.0, 1.0);
  return h < r_o + cone;
}

class WorldBuilder {
 public:
  WorldBuilder(World& world, const universe::Library& library) : world_(world), library_(library) {}

  // A material as a view sees it (shared by every part made of it and seen
  // through the same view).
  const SurfaceSpectrum* spectrum(const std::string& material, double gray_reflectance, const std::string& field,
                                  const radiometry::SpectralView& view) {
    const universe::Material& m = library_.materials.get(material, field);
    const auto key = std::make_tuple(m.name, m.gray_body ? gray_reflectance : 0.0, &view);
    auto it = index_.find(key);
    if (it != index_.end()) return world_.spectra[it->second].get();
    world_.spectra.push_back(std::make_unique<SurfaceSpectrum>(m, gray_reflectance, view));
    index_[key] = world_.spectra.size() - 1;
    return world_.spectra.back().get();
  }

  // A material made for this world alone (the cloud tops).
  const SurfaceSpectrum* own(const universe::Material& material, const radiometry::SpectralView& view) {
    world_.spectra.push_back(std::make_unique<SurfaceSpectrum>(material, 0.0, view));
    return world_.spectra.back().get();
  }

  std::vector<double> self_radiance(const std::string& name, const std::string& field) const {
    if (name.empty()) return {};
    const universe::NamedSpectrum* s = library_.spectra.find(name);
    if (!s) throw Error(Status::unknown_name, field + ": no spectrum named '" + name + "' in the spectrum table");
    const radiometry::SpectralBand& b = world_.view.spectral.band;
    return s->radiance_W_cm2_sr_um.interval_means(b.low_um, b.interval_um(), b.intervals);
  }

 private:
  World& world_;
  const universe::Library& library_;
  std::map<std::tuple<std::string, double, const radiometry::SpectralView*>, std::size_t> index_;
};

// Places one object relative to the observer; nullptr for objects that image
// nothing (sensors, the star field, shape none, an empty composite) or that
// the host has not placed yet. The surface model comes later (it needs the
// eclipse geometry of every object).
std::unique_ptr<WorldObject> place(const universe::Universe& universe, const universe::Object& o, const EngineTime& t,
                                   const World& world) {
  if (o.kind == ObjectKind::sensor || o.kind == ObjectKind::star_field) return nullptr;
  if (o.kind != ObjectKind::central_body && !o.state.valid) return nullptr;
  const std::vector<universe::ShapePart> shape = universe::shape_parts_at(o, t);
  if (shape.empty()) return nullptr;
  universe::Kinematics k = universe::kinematics_at(universe, o, t);
  auto w = std::make_unique<WorldObject>();
  EngineTime seen = t;  // when the light the sensor receives left the object
  const Vec3 observer = world.observer.position_m;
  const bool apparent = o.kind == ObjectKind::central_body && o.central_body != universe::CentralBody::earth &&
                        o.central_body != universe::CentralBody::sun;
  if (apparent) {
    // The Moon and the planets at their apparent places: where they were one
    // light time ago (iterated), displaced by the aberration of the
    // observer's geocentric velocity (first order; the Earth's orbital
    // velocity cancels against the light time of geocentric positions).
    for (int i = 0; i < 3; ++i) {
      w->light_time_s = (k.position_m - observer).norm() / constants::speed_of_light_m_per_s;
      seen = t.plus_seconds(-w->light_time_s);
      k = universe::kinematics_at(universe, o, seen);
    }
  }
  w->name = o.name;
  w->kind = o.kind;
  w->central_body = o.kind == ObjectKind::central_body;
  geometry::PlacedObject& po = w->placed;
  const bool staged = o.kind == ObjectKind::missile && !o.body.missile_stage_list->empty();
  w->parts_hide_each_other = staged;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const std::string field = staged ? o.name + ".missile_stages"
                              : o.body.shape == universe::ShapeKind::composite
                                  ? o.name + ".composite[" + std::to_string(i) + "]"
                                  : o.name + ".shape";
    po.parts.push_back(geometry::make_part(shape[i], field));
  }
  po.position_m = k.position_m - observer;
  if (apparent) {
    const Vec3 beta = world.observer.velocity_m_s / constants::speed_of_light_m_per_s;
    const Vec3 u = po.position_m.normalized();
    po.position_m += po.position_m.norm() * (beta - beta.dot(u) * u);
  }
  w->geocentric_position_m = k.position_m;
  if (w->central_body) {
    const universe::CentralBodyInfo& info = universe::central_body_info(o.central_body);
    po.body_to_frame = info.axes == universe::BodyAxes::earth_fixed ? Mat3(frames::j2000_to_earth_fixed(seen).transpose())
                                                                     : universe::body_to_j2000(o.central_body, seen);
    w->equatorial_radius_m = o.body.dimensions_m[0];
    w->polar_radius_m = o.body.dimensions_m[1];
  } else {
    po.body_to_frame = k.attitude.toRotationMatrix();
  }
  w->range_m = po.position_m.norm();
  for (const auto& part : po.parts)
    w->bounding_radius_m =
        std::max(w->bounding_radius_m, part.offset_m.norm() + geometry::shape_bounding_radius_m(part.geom));
  w->volumetric_radius_m = volumetric_radius_m(po.parts);
  if (w->central_body)
    w->disk_photometry = radiometry::DiskPhotometry(radiometry::disk_phase_law(o.central_body), o.body.rings);
  w->patch_size_m = patch_size_m(o, po.parts, world.view.fidelity);
  const universe::PointSourceModel model = o.body.point_source_model;
  w->detailed_point_source =
      model == universe::PointSourceModel::detailed || (model == universe::PointSourceModel::automatic && !w->central_body);
  return w;
}

// Aircraft and ground vehicles shade the Sun's light by their parts (their
// bounding spheres would cast round shadows on the ground).
bool shades_by_parts(ObjectKind kind) { return kind == ObjectKind::aircraft || kind == ObjectKind::ground_vehicle; }

geometry::Occulter occulter_of(const WorldObject& w) {
  if (w.central_body)
    return geometry::Occulter{w.placed.position_m, w.equatorial_radius_m, w.polar_radius_m, w.placed.body_to_frame.col(2)};
  return geometry::Occulter{w.placed.position_m, w.bounding_radius_m, w.bounding_radius_m, Vec3::UnitZ()};
}
}  // namespace

const geometry::Tessellation& WorldObject::tessellation() const {
  std::call_once(tessellated_, [this] {
    tessellation_ = geometry::tessellate(placed.parts, patch_size_m);
    const std::size_t n = tessellation_.patches.size();
    patch_cache_ = std::make_unique<std::atomic<double>[]>(n);
    for (std::size_t i = 0; i < n; ++i)
      patch_cache_[i].store(std::numeric_limits<double>::quiet_NaN(), std::memory_order_relaxed);
  });
  return tessellation_;
}

Vec3 WorldObject::normal_at(std::int32_t part, const Vec3& point_body_m) const {
  const geometry::ShapePart& sp = placed.parts[static_cast<std::size_t>(part < 0 ? 0 : part)];
  const Vec3 local = sp.orientation.conjugate() * (point_body_m - sp.offset_m);
  return (sp.orientation * geometry::shape_normal(sp.geom, local)).normalized();
}

Vec3 WorldObject::toward_observer_body() const {
  return -(placed.body_to_frame.transpose() * placed.position_m).normalized();
}

double WorldObject::sun_fraction(const Vec3& point_frame_m, const ShadowCasters* near) const {
  const SunLight& sun = world_->sun;
  const double f = geometry::solar_disk_visible_fraction(point_frame_m, sun.position_m, sun.radius_m,
                                                         near ? near->occulters[0] : occulters_[0]);
  const std::vector<const WorldObject*>& part_shadows = near ? near->part_shadows : part_shadows_;
  if (f > 0 && !part_shadows.empty() && !(central_body && point_frame_m == placed.position_m)) {
    const Vec3 to_sun = sun.position_m - point_frame_m;
    const double d = to_sun.norm();
    for (const WorldObject* o : part_shadows)
      if (geometry::parts_block_ray(o->placed, o->bounding_radius_m, point_frame_m, to_sun / d, d)) return 0.0;
  }
  return f;
}

void WorldObject::shadow_casters_near(const Vec3& centre_frame_m, double radius_m, ShadowCasters& out) const {
  const World& w = *world_;
  // Margins against can_shade's straight-cone hull of the region and the
  // light (conservative to ~1e-5 of the radii): 1 % of each radius, and the
  // reflecting layers' height (SurfaceModel::reflect raises the point).
  constexpr double kMargin = 1.01;
  const double region_m = kMargin * (radius_m + surface->layer_height_m()) + 1.0;
  const auto inflated = [&](geometry::Occulter o) {
    o.equatorial_radius_m *= kMargin;
    o.polar_radius_m *= kMargin;
    return o;
  };
  out.occulters.resize(occulters_.size());
  for (std::size_t j = 0; j < occulters_.size(); ++j) {
    const Vec3& light = j == 0 ? w.sun.position_m : w.lights[j - 1].position_m;
    const double light_radius = j == 0 ? w.sun.radius_m : w.lights[j - 1].radius_m;
    out.occulters[j].clear();
    for (const geometry::Occulter& o : occulters_[j])
      if (can_shade(centre_frame_m, region_m, light, light_radius, inflated(o))) out.occulters[j].push_back(o);
  }
  out.centre_frame_m = centre_frame_m;
  out.radius_m = radius_m;
  out.part_shadows.clear();
  for (const WorldObject* o : part_shadows_)
    if (can_shade(centre_frame_m, region_m, w.sun.position_m, w.sun.radius_m,
                  geometry::Occulter::sphere(o->placed.position_m, kMargin * o->bounding_radius_m)))
      out.part_shadows.push_back(o);
}

void WorldObject::add_reflected_irradiance(const Vec3& p, const Vec3& n, const Vec3& toward,
                                           const radiometry::Brdf& brdf, bool sun_only, std::vector<double>& out,
                                           const ShadowCasters* near, double negligible_W_cm2_sr,
                                           const char* lights_off) const {
  const World& w = *world_;
  const std::size_t count = out.size();
  // The Sun (eq. 6): E = L_tab dOmega_sun, times the visible fraction of its disc.
  const Vec3 to_sun = w.sun.position_m - p;
  // (The sign of cos(incidence) first, without the norm: a point facing
  // away, half of every globe, costs no square root and division.)
  if (w.sun.object != id && to_sun.dot(n) > 0) {
    const double d = to_sun.norm();
    const Vec3 I = to_sun / d;
    const double cos_i = I.dot(n);
    if (cos_i > 0) {
      const double f = sun_fraction(p, near);
      if (f > 0) {
        double g = f * universe::sun_projected_solid_angle_sr(d) * cos_i * brdf.value(I, toward, n);
        // A planet's resolved disc (Lambertian patches) carries its observed
        // law (issue 21): sunlight times Phase_law / Phase_Lambert at the
        // angle Sun-planet-`toward`, so that the disc's total toward the
        // observer (or a receiver) is the law's, face terms included.
        if (!disk_photometry.lambertian() && disk_photometry.law() != radiometry::DiskPhaseLaw::moon &&
            brdf.lambertian()) {
          const Vec3 centre_to_sun = (w.sun.position_m - placed.position_m).normalized();
          const double lambert = radiometry::lambertian_sphere_phase(centre_to_sun.dot(toward));
          if (lambert > 0)
            g *= disk_photometry.phase(radiometry::DiscView{centre_to_sun, toward, placed.body_to_frame}) / lambert;
        }
        if (under_atmosphere_) {  // eq. 9's T_in at the point's Sun zenith angle
          thread_local std::vector<double> T;
          w.atmosphere.surface->sun_at(cos_i, T);
          for (std::size_t i = 0; i < count; ++i) out[i] += g * w.sun.radiance[i] * T[i];
        } else if (sun_transmittance_.empty()) {
          for (std::size_t i = 0; i < count; ++i) out[i] += g * w.sun.radiance[i];
        } else {  // eq. 9's T_in
          for (std::size_t i = 0; i < count; ++i) out[i] += g * w.sun.radiance[i] * sun_transmittance_[i];
        }
      }
    }
  }
  if (sun_only) return;
  // The background light (eq. 4): E_bkg / pi, reflected whatever the BRDF.
  if (w.sky.background)
    for (std::size_t i = 0; i < count; ++i) out[i] += w.sky.background_irradiance[i] / constants::pi;
  // Eq. 9's DownWelling / pi on the Earth's surface, likewise.
  if (under_atmosphere_ && w.atmosphere.downwelling)
    w.atmosphere.downwelling->add_over_pi(n.dot(w.atmosphere.to_sun), w.atmosphere.sun_irradiance, out);
  // Every other object: its disc with its phase law (eq. 7) or its tessellation (eq. 8).
  for (std::size_t k = 0; k < w.lights.size(); ++k) {
    const ObjectLight& src = w.lights[k];
    if (src.object == id || negligible_light_[k] || (lights_off && lights_off[k])) continue;
    const Vec3 to_src = src.position_m - p;
    const WorldObject& source = *w.objects[static_cast<std::size_t>(src.object)];
    // A disc below (eq. 7; an area source too while it subtends less than
    // half area_source_solid_angle_sr here): first the sign of cos_i, then
    // whether it can matter here at all.
    const double distance2_m2 = to_src.squaredNorm(), disc_m2 = disc_area_m2(src);
    if (seen_as_disc(src, distance2_m2, w.view.fidelity)) {
      if (!(to_src.dot(n) > 0)) continue;  // (cos_i <= 0 below, but for rounding)
      // Its bound here: dOmega x the BRDF's largest N.L value x its light
      // at any phase, against kNegligibleAtPoint of the point's irradiance
      // so far (the Sun's by day), wavelength by wavelength.
      const LightSpectra& spectra = source.light_spectra();
      const std::vector<double>& bound = spectra.bound;
      // (and against negligible_W_cm2_sr: the same bound, band-integrated)
      if (disc_light_below(src, distance2_m2, brdf.max_projected_value_per_sr(), spectra, negligible_W_cm2_sr))
        continue;
      const double scale = disc_m2 / distance2_m2 * brdf.max_projected_value_per_sr() / kNegligibleAtPoint;
      std::size_t i = 0;
      while (i < bound.size() && scale * bound[i] <= out[i]) ++i;
      if (!bound.empty() && i == bound.size()) continue;
    }
    const double d = to_src.norm(), omega = disc_m2 / distance2_m2;
    if (!(d > src.radius_m)) continue;
    const Vec3 I = to_src / d;
    if (src.area_source && omega > w.view.fidelity.area_source_solid_angle_sr) {
      for (const AreaSourcePatch& a : area_source(k)) {
        const double c = a.direction.dot(n);
        if (c <= 0) continue;
        const double g = a.solid_angle_sr * c * brdf.value(a.direction, toward, n);
        for (std::size_t i = 0; i < count; ++i) out[i] += g * a.radiance[i];
      }
      continue;
    }
    const double cos_i = I.dot(n);
    if (cos_i <= 0) continue;
    const std::vector<geometry::Occulter>& occulters = near ? near->occulters[k + 1] : occulters_[k + 1];
    const double visible = occulters.empty() ? 1.0  // (d > radius: nothing hides any of it)
                                             : geometry::solar_disk_visible_fraction(p, src.position_m, src.radius_m,
                                                                                     occulters);
    if (visible <= 0) continue;
    const double g = omega * visible * cos_i * brdf.value(I, toward, n);
    const LightSpectra& spectra = source.light_spectra();
    if (g * spectra.bound_band_W_cm2_sr < negligible_W_cm2_sr) continue;
    if (!spectra.reflects) {  // eclipsed or black: no phase to weigh
      for (std::size_t i = 0; i < count; ++i) out[i] += g * spectra.emitted[i];
      continue;
    }
    const double phase = source.disk_photometry.phase(radiometry::DiscView{src.to_sun, -I, source.placed.body_to_frame});
    for (std::size_t i = 0; i < count; ++i) out[i] += g * (spectra.reflected[i] * phase + spectra.emitted[i]);
  }
}

void WorldObject::lights_negligible_in(const ShadowCasters& near, double negligible_W_cm2_sr,
                                       std::vector<char>& out) const {
  const World& w = *world_;
  out.assign(w.lights.size(), 0);
  // add_reflected_irradiance's first bound of a disc at every point of the
  // region (raised by at most the layers' height): the least distance, the
  // largest N.L value of any of its BRDFs.
  const double reach_m = near.radius_m + surface->layer_height_m();
  for (std::size_t k = 0; k < w.lights.size(); ++k) {
    const ObjectLight& src = w.lights[k];
    if (src.object == id || negligible_light_[k]) continue;
    const double d = (src.position_m - near.centre_frame_m).norm() - reach_m;
    if (!(d > src.radius_m) || !seen_as_disc(src, d * d, w.view.fidelity)) continue;
    const LightSpectra& spectra = w.objects[static_cast<std::size_t>(src.object)]->light_spectra();
    out[k] = disc_light_below(src, d * d, surface->brdf_bound_per_sr(), spectra, negligible_W_cm2_sr);
  }
}

const LightSpectra& WorldObject::light_spectra() const {
  lit_.call([this] {
    const World& w = *world_;
    const std::size_t n = w.spectral().sample_wavelengths_um.size();
    std::vector<double> srf(n, 0.0), e(n);
    std::vector<double>& emitted = light_spectra_.emitted;
    emitted.assign(n, 0.0);
    double total_area = 0, srf_weight = 0;
    // The Moon's SRF is its albedo map's mean over the disc seen (projected
    // area, as data/moon/make_albedo.py normalises the map to p over the
    // near-side disc): its law is the observed disc's. Its receivers are near
    // the observer as the Moon sees them, so the observer's disc stands for
    // theirs. (The whole sphere's mean is 0.1396 for the near side's 0.12:
    // the bitmap Moon's light was 0.16 mag too bright.) Others: the area mean.
    const bool seen_disc = surface->varying() && disk_photometry.law() == radiometry::DiskPhaseLaw::moon;
    const Vec3 toward = toward_observer_body();
    const auto add = [&](const SurfaceSite& site, double area) {
      const SurfacePoint point = surface->at(site);
      const double weight = seen_disc ? area * std::max(0.0, site.normal_body.dot(toward)) : area;
      if (surface->reflects(point)) surface->add_srf(point, weight, srf);
      srf_weight += weight;
      std::fill(e.begin(), e.end(), 0.0);
      surface->add_emission(point, e);
      for (std::size_t i = 0; i < n; ++i) emitted[i] += area * e[i];
      total_area += area;
    };
    if (surface->varying()) {
      for (const geometry::Patch& p : tessellation().patches)
        add(SurfaceSite{p.part, p.centre_body_m, p.normal_body}, p.area_m2);
    } else {
      for (std::size_t p = 0; p < placed.parts.size(); ++p)
        add(SurfaceSite{static_cast<std::int32_t>(p), Vec3::Zero(), Vec3::UnitZ()},
            geometry::shape_surface_area_m2(placed.parts[p].geom));
    }
    if (total_area > 0)
      for (std::size_t i = 0; i < n; ++i) {
        srf[i] /= srf_weight > 0 ? srf_weight : total_area;
        emitted[i] /= total_area;
      }
    const double fraction = sun_fraction(placed.position_m);
    const double sun_omega = universe::sun_projected_solid_angle_sr((w.sun.position_m - placed.position_m).norm());
    light_spectra_.reflected.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      light_spectra_.reflected[i] =
          disk_photometry.lambertian()
              ? w.sun.radiance[i] * sun_omega * fraction * srf[i] * 2.0 / (3.0 * constants::pi)
              : w.sun.radiance[i] * sun_omega * fraction * srf[i] * disk_photometry.geometric_albedo_per_srf() /
                    constants::pi;
      light_spectra_.reflects = light_spectra_.reflects || light_spectra_.reflected[i] != 0.0;
    }
    if (disk_photometry.lambertian() ||
        (disk_photometry.law() == radiometry::DiskPhaseLaw::moon && !disk_photometry.has_face_terms())) {
      light_spectra_.bound.resize(n);
      for (std::size_t i = 0; i < n; ++i) light_spectra_.bound[i] = light_spectra_.reflected[i] + emitted[i];
      light_spectra_.bound_band_W_cm2_sr = w.view.spectral.integrate(light_spectra_.bound);
    }
  });
  return light_spectra_;
}

const std::vector<WorldObject::AreaSourcePatch>& WorldObject::area_source(std::size_t light) const {
  std::lock_guard<std::mutex> lock(area_mutex_);
  auto it = area_sources_.find(light);
  if (it != area_sources_.end()) return it->second;
  const WorldObject& s = *world_->objects[static_cast<std::size_t>(world_->lights[light].object)];
  const Vec3 receiver = placed.position_m;
  std::vector<AreaSourcePatch> patches;
  for (const geometry::Patch& q : s.tessellation().patches) {
    const Vec3 centre = s.to_frame(q.centre_body_m);
    const Vec3 normal = s.placed.body_to_frame * q.normal_body;
    const Vec3 d = receiver - centre;
    const double dist = d.norm(), facing = normal.dot(d);
    if (facing <= 0 || !(dist > 0)) continue;
    const Vec3 toward_receiver = d / dist;
    patches.push_back(AreaSourcePatch{-toward_receiver, q.area_m2 * (facing / dist) / (dist * dist),
                                      s.spectral_radiance(q.part, q.centre_body_m, q.normal_body, toward_receiver, true)});
  }
  return area_sources_.emplace(light, std::move(patches)).first->second;
}

void WorldObject::spectral_radiance_into(std::int32_t part, const Vec3& point_body_m, const Vec3& normal_body,
                                         const Vec3& toward, bool sun_only, std::vector<double>& out,
                                         std::vector<double>& E, bool skip_negligible_emission) const {
  out.assign(world_->view.spectral.sample_wavelengths_um.size(), 0.0);
  const SurfacePoint point = surface->at(SurfaceSite{part, point_body_m, normal_body});
  if (surface->reflects(point)) {
    const Vec3 p = to_frame(point_body_m), n = placed.body_to_frame * normal_body;
    surface->reflect(
        point,
        [&](const radiometry::Brdf& brdf, double height_m, std::vector<double>& into) {
          add_reflected_irradiance(p + height_m * n, n, toward, brdf, sun_only, into);
        },
        out, E);
    // (as effective_radiance leaves out what cannot reach kNegligible of the reflected light)
    if (skip_negligible_emission && world_->view.spectral.integrate(out) > surface->emission_bound() / kNegligible)
      return;
  }
  surface->add_emission(point, out);
}

std::vector<double> WorldObject::spectral_radiance(std::int32_t part, const Vec3& point_body_m, const Vec3& normal_body,
                                                   const Vec3& toward, bool sun_only) const {
  std::vector<double> out, E;
  spectral_radiance_into(part, point_body_m, normal_body, toward, sun_only, out, E);
  return out;
}

double WorldObject::effective_radiance(std::int32_t part, const Vec3& point_body_m, const Vec3& normal_body,
                                       bool interpolated, const ShadowCasters* near,
                                       const SurfacePoint* surface_point) const {
  if (plain()) return plain_radiance(part);
  if (under_atmosphere_) {  // eq. 9 interval by interval: the path changes with the point
    thread_local std::vector<double> L, E;  // per-sample scratch (eq. 8 sources below allocate their own)
    const World& w = *world_;
    const Vec3 d = to_frame(point_body_m).normalized();
    const SurfacePoint point = surface_point ? *surface_point : surface->at(SurfaceSite{part, point_body_m, normal_body});
    // (Under clouds the exact sum: their light comes from another height.)
    const auto table = surface->tabulated() || point.cloud_fraction > 0.0
                           ? w.atmosphere.surface_emission.end()
                           : w.atmosphere.surface_emission.find(point.spectrum);
    if (table == w.atmosphere.surface_emission.end()) {
      spectral_radiance_into(part, point_body_m, normal_body, -d, false, L, E, true);
      to_sensor(L, point_body_m, normal_body, false);
      return w.view.spectral.integrate(L) + w.atmosphere.scatter_band(d);
    }
    // The reflected light interval by interval through the path, the
    // emission through it from PathEmission's tables (as
    // spectral_radiance_into, less what cannot reach kNegligible of the
    // reflected light).
    L.assign(w.view.spectral.sample_wavelengths_um.size(), 0.0);
    bool emits = true;
    if (surface->reflects(point)) {
      const Vec3 p = to_frame(point_body_m), n = placed.body_to_frame * normal_body;
      surface->reflect(
          point,
          [&](const radiometry::Brdf& brdf, double height_m, std::vector<double>& into) {
            add_reflected_irradiance(p + height_m * n, n, -d, brdf, false, into, near);
          },
          L, E);
      emits = !(w.view.spectral.integrate(L) > surface->emission_bound() / kNegligible);
    }
    double emitted = 0;
    if (emits) {  // emissivity 1 - s SRF: s (1 - SRF) + (1 - s) of a black body (SurfaceModel::add_emission)
      const double mu = (placed.body_to_frame * normal_body).dot(-d), T = surface->temperature_K(point);
      const double s = point.reflectance_scale;
      emitted = s * table->second.scale * table->second.table->radiance(mu, T);
      if (s != 1.0) emitted += (1.0 - s) * w.atmosphere.black_emission->radiance(mu, T);
    }
    to_sensor(L, point_body_m, normal_body, false);
    return w.view.spectral.integrate(L) + emitted + w.atmosphere.scatter_band(d);
  }
  const SurfacePoint point = surface_point ? *surface_point : surface->at(SurfaceSite{part, point_body_m, normal_body});
  const SurfacePoint* one = &point;
  double L = 0;
  effective_radiances(&one, 1, near, &L, interpolated);
  return L;
}

double WorldObject::negligible_light_W_cm2_sr(const SurfacePoint& point, double emitted_W_cm2_sr) const {
  // kNegligible / (the number of sources) of the point's own emission: all
  // of them together, less than kNegligible of it (the point's layers pass
  // at most srf_bound of each).
  return emitted_W_cm2_sr > 0 ? kNegligible / static_cast<double>(world_->lights.size()) * emitted_W_cm2_sr /
                                    surface->srf_bound(point)
                              : 0.0;
}

double WorldObject::reflected_radiance(const SurfacePoint& point, const ShadowCasters* near, bool& emits,
                                       double negligible, const char* lights_off) const {
  double reflected = 0;
  if (surface->reflects(point)) {
    const Vec3 p = to_frame(point.site.point_body_m), n = placed.body_to_frame * point.site.normal_body,
               toward = -p.normalized();
    thread_local std::vector<double> E, L;  // per-sample scratch: no allocation per call
    L.resize(world_->view.spectral.sample_wavelengths_um.size());
    surface->reflect(
        point,
        [&](const radiometry::Brdf& brdf, double height_m, std::vector<double>& into) {
          add_reflected_irradiance(p + height_m * n, n, toward, brdf, false, into, near, negligible, lights_off);
        },
        L, E);
    reflected = view().integrate(L);
  }
  // Self-emission that cannot reach kNegligible of the reflected
  // light (a visible band by day: B(0.75 um, 380 K) ~ 1e-22 of the Sun's) is
  // left out: it would change the sum by less than that, relative.
  emits = !(reflected > surface->emission_bound() / kNegligible);
  return reflected;
}

void WorldObject::effective_radiances(const SurfacePoint* const* points, std::size_t n, const ShadowCasters* near,
                                      double* out, bool interpolated) const {
  if (under_atmosphere_) {
    for (std::size_t k = 0; k < n; ++k) {
      const SurfaceSite& site = points[k]->site;
      out[k] = effective_radiance(site.part, site.point_body_m, site.normal_body, interpolated, near, points[k]);
    }
    return;
  }
  // (their temperatures together)
  if (emission_first_) {
    surface->emission_radiances(points, n, interpolated, out);
    // Each reflecting point's threshold for other objects' light, and the
    // lights that cannot reach the least of them anywhere in the region the
    // points lie in.
    thread_local std::vector<double> negligible;
    thread_local std::vector<char> off;
    negligible.resize(n);
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < n; ++k) {
      negligible[k] = surface->reflects(*points[k]) ? negligible_light_W_cm2_sr(*points[k], out[k]) : 0.0;
      if (surface->reflects(*points[k])) least = std::min(least, negligible[k]);
    }
    const char* lights_off = nullptr;
    if (near && !world_->lights.empty() && least > 0 && std::isfinite(least)) {
      lights_negligible_in(*near, least, off);
      lights_off = off.data();
    }
    for (std::size_t k = 0; k < n; ++k) {
      bool emits = true;
      const double reflected = reflected_radiance(*points[k], near, emits, negligible[k], lights_off);
      out[k] = emits ? out[k] + reflected + path_radiance_W_cm2_sr_ : reflected + path_radiance_W_cm2_sr_;
    }
    return;
  }
  // The reflected light point by point, then the emission of those it can
  // matter for.
  constexpr std::size_t kBatch = 64;
  const SurfacePoint* emitting[kBatch];
  std::size_t at[kBatch];
  double reflected[kBatch], emitted[kBatch];
  for (std::size_t first = 0; first < n; first += kBatch) {
    const std::size_t m = std::min(kBatch, n - first);
    std::size_t count = 0;
    for (std::size_t k = 0; k < m; ++k) {
      bool emits = true;
      reflected[k] = reflected_radiance(*points[first + k], near, emits, 0.0);
      if (!emits) {
        out[first + k] = reflected[k] + path_radiance_W_cm2_sr_;
        continue;
      }
      emitting[count] = points[first + k];
      at[count++] = k;
    }
    surface->emission_radiances(emitting, count, interpolated, emitted);
    for (std::size_t j = 0; j < count; ++j)
      out[first + at[j]] = emitted[j] + reflected[at[j]] + path_radiance_W_cm2_sr_;
  }
}

double WorldObject::patch_radiance(std::int32_t patch) const {
  const geometry::Patch& p = tessellation().patches[static_cast<std::size_t>(patch)];
  if (plain()) return plain_radiance(p.part);
  std::atomic<double>& cached = patch_cache_[static_cast<std::size_t>(patch)];
  double L = cached.load(std::memory_order_relaxed);
  if (std::isnan(L)) {  // two threads may both compute it: the same value
    L = effective_radiance(p.part, p.centre_body_m, p.normal_body);
    cached.store(L, std::memory_order_relaxed);
  }
  return L;
}

void WorldObject::shading_point(std::int32_t part, const Vec3& point_body_m, const Vec3& hit_normal_body,
                                Vec3& shade_point_body, Vec3& normal_body, std::int32_t facet) const {
  if (shades_each_sample()) {
    shade_point_body = point_body_m;
    normal_body = hit_normal_body;
    return;
  }
  const std::int32_t k =
      geometry::patch_at_facet(tessellation(), placed.parts, part, facet, point_body_m, hit_normal_body);
  const geometry::Patch& p = tessellation().patches[static_cast<std::size_t>(k)];
  shade_point_body = p.centre_body_m;
  normal_body = p.normal_body;
}

bool WorldObject::shades_each_sample() const {
  // (under its atmosphere the Earth is shaded at each sample in coarse mode
  // too: eq. 9's path is the sample's line of sight, not the patch centre's)
  return world_->view.fidelity.scene_mode != SceneMode::coarse || under_atmosphere_;
}

double WorldObject::radiance_at(std::int32_t part, const Vec3& point_body_m, const Vec3& hit_normal_body,
                                std::int32_t facet) const {
  if (plain()) return plain_radiance(part);
  if (shades_each_sample()) return effective_radiance(part, point_body_m, hit_normal_body, true);
  return patch_radiance(geometry::patch_at_facet(tessellation(), placed.parts, part, facet, point_body_m, hit_normal_body));
}

double WorldObject::projected_area_m2() const {
  const Vec3 v = toward_observer_body();
  if (placed.parts.size() == 1) {
    const double a = geometry::analytic_projected_area_m2(placed.parts[0], v);
    if (a >= 0) return a;
  }
  return geometry::projected_area_m2(placed.parts, tessellation(), v);
}

double WorldObject::point_irradiance_W_cm2() const {
  const double r2 = range_m * range_m;
  // (the spectral vector is at the sensor already: T_out applied)
  if (!detailed_point_source) return world_->view.spectral.integrate(point_spectral_irradiance());
  if (placed.parts.size() == 1 && plain()) return plain_radiance(0) * (projected_area_m2() / r2);
  if (hidden_by_window()) {  // parts may hide each other: each patch as much as is visible
    const std::vector<double>& omega = visible_window().patch_solid_angle_sr;
    double sum = 0;
    for (std::size_t k = 0; k < omega.size(); ++k)
      if (omega[k] > 0) sum += patch_radiance(static_cast<std::int32_t>(k)) * omega[k];
    return sum;
  }
  return visible_patch_sum(tessellation(), [this](std::int32_t k) { return patch_radiance(k); }) / r2;
}

const VisibleWindow& WorldObject::visible_window() const {
  std::call_once(windowed_, [this] { window_ = window(kVisibleWindowRays, 1); });
  return window_;
}

VisibleWindow WorldObject::window(std::int64_t rays_across, unsigned threads) const {
  VisibleWindow out;
  const geometry::Tessellation& t = tessellation();
  out.patch_solid_angle_sr.assign(t.patches.size(), 0.0);
  const double distance = seen.position_m.norm();
  if (!(distance > bounding_radius_m) || rays_across < 1) return out;
  // rays_across cells of angle `step` across the bounding disc, on the
  // tangent plane about the line of sight (u, v); a cell's solid angle is
  // cos^3 theta sec^2 x sec^2 y step^2 (theta off the line of sight).
  const Vec3 los = seen.position_m / distance;
  const Vec3 u = los.cross(std::fabs(los.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX()).normalized();
  const Vec3 v = los.cross(u);
  const double half = std::asin(bounding_radius_m / distance);
  const double step = 2.0 * half / static_cast<double>(rays_across);
  std::vector<Vec3> directions;
  std::vector<double> omega;
  for (std::int64_t j = 0; j < rays_across; ++j)
    for (std::int64_t i = 0; i < rays_across; ++i) {
      const double x = -half + (static_cast<double>(i) + 0.5) * step, y = -half + (static_cast<double>(j) + 0.5) * step;
      if (x * x + y * y > half * half) continue;  // outside the bounding disc
      const double tx = std::tan(x), ty = std::tan(y);
      const double cos_theta = 1.0 / std::sqrt(1.0 + tx * tx + ty * ty);
      directions.push_back((los + tx * u + ty * v) * cos_theta);
      omega.push_back(cos_theta * cos_theta * cos_theta * (1.0 + tx * tx) * (1.0 + ty * ty) * step * step);
    }
  std::vector<geometry::Hit> hits;
  world_->caster.cast(directions, hits, threads);
  for (std::size_t k = 0; k < hits.size(); ++k) {
    const geometry::Hit& h = hits[k];
    if (h.object_id != id) continue;  // the sky, or another object in front
    const Vec3 normal_body = direction_to_body(h.normal_frame);
    const std::int32_t patch = geometry::patch_at_facet(t, placed.parts, h.part, h.facet, h.point_body_m, normal_body);
    out.rays.push_back(VisibleWindow::Ray{directions[k], patch, omega[k], h.part, h.point_body_m, normal_body, h.facet});
    out.patch_solid_angle_sr[static_cast<std::size_t>(patch)] += omega[k];
  }
  return out;
}

double WorldObject::detailed_point_irradiance_W_cm2(double patch_edge_m) const {
  const geometry::Tessellation t = geometry::tessellate(placed.parts, patch_edge_m);
  return visible_patch_sum(t, [&](std::int32_t k) {
           const geometry::Patch& p = t.patches[static_cast<std::size_t>(k)];
           return effective_radiance(p.part, p.centre_body_m, p.normal_body);
         }) / (range_m * range_m);
}

template <class PatchRadiance>
double WorldObject::visible_patch_sum(const geometry::Tessellation& t, PatchRadiance radiance) const {
  // The sum over visible patches of L dOmega (ERRATA eq. 11), times R^2.
  const Vec3 v = toward_observer_body();
  double sum = 0;
  for (std::size_t k = 0; k < t.patches.size(); ++k) {
    const geometry::Patch& patch = t.patches[k];
    const double facing = patch.normal_body.dot(v);
    if (facing > 0 && !(parts_hide_each_other && patch_hidden(patch, v)))
      sum += radiance(static_cast<std::int32_t>(k)) * facing * patch.area_m2;
  }
  return sum;
}

bool WorldObject::patch_hidden(const geometry::Patch& patch, const Vec3& v) const {
  const double lift = 1e-9 * std::max(bounding_radius_m, 1e-3);  // off the patch's own surface
  for (std::size_t q = 0; q < placed.parts.size(); ++q) {
    if (static_cast<std::int32_t>(q) == patch.part) continue;
    const geometry::ShapePart& sp = placed.parts[q];
    const Vec3 o = sp.orientation.conjugate() * (patch.centre_body_m + lift * patch.normal_body - sp.offset_m);
    if (geometry::shape_contains(sp.geom, o)) return true;
    double t = 0;
    Vec3 n;
    if (geometry::intersect_shape(sp.geom, o, sp.orientation.conjugate() * v, 0.0,
                                  std::numeric_limits<double>::infinity(), t, n))
      return true;
  }
  return false;
}

std::vector<double> WorldObject::point_spectral_irradiance() const {
  const World& w = *world_;
  std::vector<double> E(w.view.spectral.sample_wavelengths_um.size(), 0.0);
  const double r2 = range_m * range_m;
  if (!detailed_point_source && light_ >= 0 && !under_atmosphere_) {  // (under its air the Earth's paths vary: summed)
    // Eq. 7 toward the observer: [E_sun p / pi Phase(psi) + eps B(T)] dOmega.
    const LightSpectra& self = light_spectra();
    const double omega = constants::pi * volumetric_radius_m * volumetric_radius_m / r2;
    const Vec3 to_observer = -placed.position_m / range_m;
    const double phase = disk_photometry.phase(
        radiometry::DiscView{w.lights[static_cast<std::size_t>(light_)].to_sun, to_observer, placed.body_to_frame});
    for (std::size_t i = 0; i < E.size(); ++i) E[i] = (self.reflected[i] * phase + self.emitted[i]);
    E = at_sensor(std::move(E));
    for (double& e : E) e *= omega;
    return E;
  }
  const Vec3 v = toward_observer_body();
  const Vec3 toward = placed.body_to_frame * v;
  const geometry::Tessellation& t = tessellation();
  const std::vector<double>* visible = hidden_by_window() ? &visible_window().patch_solid_angle_sr : nullptr;
  for (std::size_t k = 0; k < t.patches.size(); ++k) {
    const geometry::Patch& patch = t.patches[k];
    // dOmega as point_irradiance_W_cm2 takes it
    const double omega = visible ? (*visible)[k]
                         : parts_hide_each_other && patch_hidden(patch, v)
                             ? 0.0
                             : std::max(0.0, patch.normal_body.dot(v)) * patch.area_m2 / r2;
    if (!(omega > 0)) continue;
    const std::vector<double> L = spectral_radiance(patch.part, patch.centre_body_m, patch.normal_body, toward);
    const std::vector<double> received = at_sensor(L, patch.centre_body_m, patch.normal_body);
    for (std::size_t i = 0; i < E.size(); ++i) E[i] += received[i] * omega;
  }
  return E;
}

std::vector<double> WorldObject::at_sensor(std::vector<double> spectrum, const Vec3& point_body_m,
                                           const Vec3& normal_body) const {
  to_sensor(spectrum, point_body_m, normal_body);
  return spectrum;
}

void WorldObject::to_sensor(std::vector<double>& spectrum, const Vec3& point_body_m, const Vec3& normal_body,
                            bool spectral_scatter) const {
  if (under_atmosphere_) {
    thread_local std::vector<double> T, L;
    const Vec3 toward = -to_frame(point_body_m).normalized();
    world_->atmosphere.surface->view_at((placed.body_to_frame * normal_body).dot(toward), T, L);
    for (std::size_t i = 0; i < spectrum.size(); ++i) spectrum[i] = spectrum[i] * T[i] + L[i];
    if (spectral_scatter) world_->atmosphere.add_scatter(-toward, spectrum);  // eq. 9's L_scatter
    return;
  }
  const std::vector<double>& T = view().transmittance;
  if (!T.empty())
    for (std::size_t i = 0; i < spectrum.size(); ++i) spectrum[i] *= T[i];
  if (!path_spectral_.empty())
    for (std::size_t i = 0; i < spectrum.size(); ++i) spectrum[i] += path_spectral_[i];
}

Eq9Terms WorldObject::eq9_terms(std::int32_t part, const Vec3& point_body_m, const Vec3& normal_body) const {
  Eq9Terms t;
  const World& w = *world_;
  const std::size_t n = w.view.spectral.sample_wavelengths_um.size();
  const Vec3 point = to_frame(point_body_m), toward = -point.normalized();
  t.surface = spectral_radiance(part, point_body_m, normal_body, toward);
  t.downwelling.assign(n, 0.0);
  t.transmittance.assign(n, 1.0);
  t.path_thermal.assign(n, 0.0);
  t.path_scatter.assign(n, 0.0);
  if (under_atmosphere_) {
    if (w.atmosphere.downwelling) {
      const SurfacePoint p = surface->at(SurfaceSite{part, point_body_m, normal_body});
      if (surface->reflects(p)) {
        w.atmosphere.downwelling->add_over_pi((placed.body_to_frame * normal_body).dot(w.atmosphere.to_sun),
                                              w.atmosphere.sun_irradiance, t.downwelling);
        std::vector<double> srf(n, 0.0);
        surface->add_srf(p, 1.0, srf);
        for (std::size_t i = 0; i < n; ++i) t.downwelling[i] *= srf[i];
      }
    }
    w.atmosphere.surface->view_at((placed.body_to_frame * normal_body).dot(toward), t.transmittance, t.path_thermal);
    w.atmosphere.add_scatter(-toward, t.path_scatter);
  } else {
    if (!view().transmittance.empty()) t.transmittance = view().transmittance;
    if (!path_spectral_.empty())
      for (std::size_t i = 0; i < n; ++i) {
        t.path_scatter[i] = path_scatter_[i];
        t.path_thermal[i] = path_spectral_[i] - path_scatter_[i];
      }
  }
  t.at_sensor = at_sensor(t.surface, point_body_m, normal_body);
  return t;
}

const radiometry::SpectralView& WorldObject::view() const {
  return seen_through_ ? *seen_through_ : world_->view.spectral;
}

namespace {
// The node j below x (clamped to [0, 1]) among the nodes mu = (k / (n -
// 1))^2 of SurfacePaths (the last below 1: at most n - 2), and the weight f
// of node j + 1 in the linear interpolation between them. Found from
// sqrt(x) (n - 1), then stepped to the right node (rounding).
void node_below(const std::vector<double>& mu, double x, std::size_t& j, double& f) {
  const double m = std::clamp(x, 0.0, 1.0);
  const std::size_t n = mu.size();
  std::size_t k = std::min(static_cast<std::size_t>(std::sqrt(m) * static_cast<double>(n - 1)), n - 2);
  while (k > 0 && mu[k] > m) --k;
  while (k + 2 < n && mu[k + 1] <= m) ++k;
  j = k;
  f = mu[j + 1] > mu[j] ? (m - mu[j]) / (mu[j + 1] - mu[j]) : 0.0;
}

// Linear interpolation between the rows of a table over mu.
void interpolate_rows(const std::vector<double>& mu, const std::vector<std::vector<double>>& rows, double x,
                      std::vector<double>& out) {
  std::size_t j = 0;
  double f = 0;
  node_below(mu, x, j, f);
  const std::vector<double>& a = rows[j];
  const std::vector<double>& b = rows[j + 1];
  out.resize(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) out[i] = a[i] + f * (b[i] - a[i]);
}

// The surface tables for an observer at altitude H: paths from a point of
// the equator at view (and Sun) zenith cosines mu, on `nodes` nodes (the
// fidelity's atmosphere_surface_nodes).
SurfacePaths surface_paths(const WorldAtmosphere& a, double observer_altitude_m, std::int64_t nodes) {
  const int kSurfacePathNodes = static_cast<int>(std::max<std::int64_t>(2, nodes));
  SurfacePaths t;
  const atmosphere::AtmosphereProfile& profile = *a.profile;
  const Vec3 up = a.earth.pole.unitOrthogonal();
  const Vec3 across = a.earth.pole.cross(up);
  const Vec3 ground = a.earth.centre_m + a.earth.equatorial_radius_m * up;
  const double top = a.earth.equatorial_radius_m + profile.top_altitude_m();
  const double r_observer = a.earth.equatorial_radius_m + std::min(observer_altitude_m, profile.top_altitude_m() + 1.0);
  const atmosphere::Densities air = profile.at(0.0);
  const atmosphere::RefractionConstants ground_refraction = atmosphere::refraction_constants(
      air.pressure_Pa, air.temperature_K, atmosphere::relative_humidity_pct(air.h2o_m3, air.temperature_K) / 100.0,
      0.5 * (a.optics->band().low_um + a.optics->band().high_um));
  for (int k = 0; k < kSurfacePathNodes; ++k) {
    const double mu = std::pow(static_cast<double>(k) / (kSurfacePathNodes - 1), 2.0);
    t.mu.push_back(mu);
    const Vec3 u = mu * up + std::sqrt(std::max(0.0, 1.0 - mu * mu)) * across;
    // Where the line of sight reaches the observer's altitude (or leaves the
    // atmosphere): the path runs from there to the ground, observer first.
    const Vec3 rel = ground - a.earth.centre_m;
    const double b = rel.dot(u), c = rel.squaredNorm() - std::pow(std::min(r_observer, top), 2.0);
    const double reach = -b + std::sqrt(std::max(0.0, b * b - c));
    const atmosphere::PathColumns view = atmosphere::path_between(profile, a.earth, ground + reach * u, ground);
    std::vector<double> T, L;
    a.optics->transmittance(view, T);
    a.optics->path_radiance(view, L);
    t.view_T.push_back(std::move(T));
    t.view_L.push_back(std::move(L));
    // The Sun at true zenith cosine mu is seen higher by the refraction at the ground.
    bool below = false;
    const double e = std::asin(mu), seen = e + atmosphere::refraction_from_true_rad(ground_refraction, e);
    const Vec3 toward_sun = std::sin(seen) * up + std::cos(seen) * across;
    const atmosphere::PathColumns sun =
        atmosphere::refracted_path_to_space(profile, a.earth, ground, toward_sun, below, true);
    std::vector<double> S(static_cast<std::size_t>(a.optics->band().intervals), 0.0);
    if (!below) a.optics->transmittance(sun, S);
    t.sun_T.push_back(std::move(S));
  }
  return t;
}
}  // namespace

void SurfacePaths::view_at(double mu_view, std::vector<double>& T, std::vector<double>& L) const {
  interpolate_rows(mu, view_T, mu_view, T);
  interpolate_rows(mu, view_L, mu_view, L);
}

void SurfacePaths::sun_at(double mu_sun, std::vector<double>& T) const { interpolate_rows(mu, sun_T, mu_sun, T); }

std::shared_ptr<const PathEmission> SurfacePaths::emission(const radiometry::SpectralView& view,
                                                           const std::vector<double>& weights) const {
  std::vector<double> key = weights;
  key.insert(key.end(), view.sample_wavelengths_um.begin(), view.sample_wavelengths_um.end());
  key.insert(key.end(), view.transmittance.begin(), view.transmittance.end());
  key.push_back(view.band.interval_um());
  const std::lock_guard<std::mutex> lock(emission_cache->mutex);
  auto& tables = emission_cache->tables;
  const auto it = tables.find(key);
  if (it != tables.end()) return it->second;
  if (tables.size() >= 64) tables.clear();  // bounded: worlds keep what they hold
  return tables.emplace(std::move(key), std::make_shared<const PathEmission>(*this, view, weights)).first->second;
}

PathEmission::PathEmission(const SurfacePaths& paths, const radiometry::SpectralView& view,
                           const std::vector<double>& weights)
    : mu_(paths.mu) {
  for (const std::vector<double>& T : paths.view_T) {
    std::vector<double> w(weights.size());
    bool any = false;
    for (std::size_t i = 0; i < w.size(); ++i) {
      w[i] = weights[i] * T[i] * (view.transmittance.empty() ? 1.0 : view.transmittance[i]);
      any = any || w[i] > 0;
    }
    tables_.push_back(any ? std::make_unique<radiometry::BandPlanckTable>(view.band, view.sample_wavelengths_um,
                                                                          std::move(w))
                          : nullptr);
  }
}

double PathEmission::radiance(double mu_view, double temperature_K) const {
  std::size_t j = 0;
  double f = 0;
  node_below(mu_, mu_view, j, f);
  const auto at = [&](std::size_t k) { return tables_[k] ? tables_[k]->radiance(temperature_K) : 0.0; };
  const double below = f < 1 ? at(j) : 0.0;
  return f > 0 ? below + f * (at(j + 1) - below) : below;
}

atmosphere::PathColumns WorldAtmosphere::path_to(const Vec3& point_m) const {
  atmosphere::PathColumns c;
  if (!on()) return c;
  const double range = point_m.norm();
  bool ground = false;
  if (observer_inside && range > 0 && atmosphere::altitude_m(earth, point_m) >= profile->top_altitude_m())
    c = atmosphere::refracted_path_to_space(*profile, earth, Vec3::Zero(), apparent_direction(point_m / range), ground);
  if (!c.crosses || ground) c = atmosphere::path_between(*profile, earth, Vec3::Zero(), point_m);
  return c;
}

void WorldAtmosphere::seen_from(const Vec3& point_m, std::vector<double>& T, std::vector<double>& L,
                                std::vector<double>& S) const {
  T.clear();
  L.clear();
  S.clear();
  const atmosphere::PathColumns c = path_to(point_m);
  if (!c.crosses) return;
  const atmosphere::ScatterPath path = atmosphere::ScatterPath::make(*optics, c);
  T = path.terms.transmittance;
  L = path.terms.thermal;
  S.assign(L.size(), 0.0);
  if (sunlight)
    atmosphere::add_single_scatter(path, -earth.centre_m, point_m.normalized(), to_sun, sun_irradiance, *sunlight, S);
}

double WorldAtmosphere::air_mass(const atmosphere::PathColumns& path) const {
  return on() ? path.air_m2 / profile->vertical_columns_above(0.0).air_m2 : 0.0;
}

double WorldAtmosphere::air_mass_toward(const Vec3& direction) const {
  if (!on()) return 0.0;
  bool ground = false;
  return air_mass(observer_inside
                      ? atmosphere::refracted_path_to_space(*profile, earth, Vec3::Zero(), apparent_direction(direction),
                                                            ground, false)
                      : atmosphere::path_to_space(*profile, earth, Vec3::Zero(), direction, false));
}

Vec3 WorldAtmosphere::apparent_direction(const Vec3& d, double fraction) const {
  if (!on() || !observer_inside || !(fraction > 0)) return d;
  const double e = std::asin(std::clamp(d.dot(zenith), -1.0, 1.0));
  Vec3 horizontal = d - d.dot(zenith) * zenith;
  if (!(horizontal.norm() > 1e-12)) return d;  // the zenith: no refraction
  horizontal.normalize();
  const double apparent = e + fraction * atmosphere::refraction_from_true_rad(refraction, e);
  return std::cos(apparent) * horizontal + std::sin(apparent) * zenith;
}

double WorldAtmosphere::refraction_fraction(const Vec3& point_m) const {
  const double range = point_m.norm();
  if (!on() || !observer_inside || !(range > 0)) return 0.0;
  const Vec3 d = point_m / range;
  const double R = atmosphere::refraction_from_true_rad(refraction, std::asin(std::clamp(d.dot(zenith), -1.0, 1.0)));
  if (!(R > 0)) return 0.0;
  const atmosphere::ChordRefraction c =
      atmosphere::chord_refraction(*profile, earth, Vec3::Zero(), apparent_direction(d), range);
  // Over the ray's own bending where it reaches space (the refraction
  // formula's share); over the formula's where the ray meets the ground.
  const double share = c.bending_rad > 0 ? c.chord_rad / c.bending_rad : c.chord_rad / R;
  return std::clamp(share, 0.0, 1.0);
}

std::vector<double> WorldAtmosphere::to_space(const Vec3& point_m, const Vec3& direction) const {
  std::vector<double> T;
  if (!on()) return T;
  atmosphere::PathColumns c;
  bool ground = false;
  // From the observer the ray leaves along the apparent direction (a point
  // elsewhere is taken along the true one: the Sun low over an aircraft is
  // seen through a little more air than it should).
  const Vec3 launch = point_m.squaredNorm() == 0.0 ? apparent_direction(direction) : direction;
  if (atmosphere::altitude_m(earth, point_m) < profile->top_altitude_m())
    c = atmosphere::refracted_path_to_space(*profile, earth, point_m, launch, ground);
  else
    c = atmosphere::path_to_space(*profile, earth, point_m, direction);
  if (ground) return std::vector<double>(static_cast<std::size_t>(optics->band().intervals), 0.0);
  if (c.crosses) optics->transmittance(c, T);
  return T;
}

double WorldAtmosphere::scatter_band(const Vec3& d) const {
  return (sky ? sky->scatter_band(d) : 0.0) + (moon_sky ? moon_sky->scatter_band(d) : 0.0);
}

void WorldAtmosphere::add_scatter(const Vec3& d, std::vector<double>& out) const {
  thread_local std::vector<double> S;
  for (const SkyView* v : {sky.get(), moon_sky.get()}) {
    if (!v) continue;
    v->scatter(d, S);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += S[i];
  }
}

double World::sky_radiance(const Vec3& d) const {
  double L = 0;
  if (atmosphere.sky && atmosphere.sky->sky_band(d, L))
    return atmosphere.moon_sky ? L + atmosphere.moon_sky->scatter_band(d) : L;
  return sky.background_radiance_W_cm2_sr;
}

void World::sky_spectrum(const Vec3& d, std::vector<double>& out) const {
  if (atmosphere.sky && atmosphere.sky->sky(d, out)) {
    if (atmosphere.moon_sky) {
      thread_local std::vector<double> S;
      atmosphere.moon_sky->scatter(d, S);
      for (std::size_t i = 0; i < out.size(); ++i) out[i] += S[i];
    }
    return;
  }
  out.assign(view.spectral.sample_wavelengths_um.size(), 0.0);
  if (sky.background)
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = sky.background_irradiance[i] / constants::pi;
}

Eq9Terms World::sky_terms(const Vec3& d) const {
  Eq9Terms t;
  const std::size_t n = view.spectral.sample_wavelengths_um.size();
  t.surface.assign(n, 0.0);
  if (sky.background)
    for (std::size_t i = 0; i < n; ++i) t.surface[i] = sky.background_irradiance[i] / constants::pi;
  t.downwelling.assign(n, 0.0);
  t.transmittance.assign(n, 1.0);
  t.path_thermal.assign(n, 0.0);
  t.path_scatter.assign(n, 0.0);
  if (atmosphere.sky && atmosphere.sky->path(d, t.transmittance, t.path_thermal)) atmosphere.add_scatter(d, t.path_scatter);
  sky_spectrum(d, t.at_sensor);
  return t;
}

const WorldObject* World::find(const std::string& name) const {
  for (const auto& o : objects)
    if (o->name == name) return o.get();
  return nullptr;
}

// Entries each of the engine's world caches keeps at most.
constexpr std::size_t kWorldCacheEntries = 16;

std::shared_ptr<const atmosphere::PathOptics> WorldCache::optics(const universe::AtmosphereSettings& settings,
                                                                 const std::string& data_dir,
                                                                 const radiometry::SpectralBand& band,
                                                                 double sub_sample_spacing_cm1,
                                                                 std::int64_t layer_stride) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [s, dir, low, high, n, spacing, stride, optics] : optics_)
    if (s == settings && dir == data_dir && low == band.low_um && high == band.high_um && n == band.intervals &&
        spacing == sub_sample_spacing_cm1 && stride == layer_stride)
      return optics;
  auto made = std::make_shared<const atmosphere::PathOptics>(
      atmosphere::AtmosphereProfile::make(settings, data_dir, static_cast<std::size_t>(layer_stride)), settings,
      data_dir, band, sub_sample_spacing_cm1);
  if (optics_.size() >= kWorldCacheEntries) optics_.clear();  // bounded: worlds keep what they hold
  optics_.emplace_back(settings, data_dir, band.low_um, band.high_um, band.intervals, sub_sample_spacing_cm1,
                       layer_stride, made);
  return made;
}

namespace {
// The entry of a cache map for key, made by `make` if new (the map is
// cleared when full: worlds keep what they hold; an aircraft's altitude
// changes every frame).
template <class Key, class T>
std::shared_ptr<const T> cached(std::map<Key, std::shared_ptr<const T>>& map, const Key& key,
                                const std::function<T()>& make) {
  auto it = map.find(key);
  if (it != map.end()) return it->second;
  if (map.size() >= kWorldCacheEntries) map.clear();
  return map.emplace(key, std::make_shared<const T>(make())).first->second;
}
}  // namespace

std::shared_ptr<const SurfacePaths> WorldCache::surface(const std::shared_ptr<const atmosphere::PathOptics>& optics,
                                                        double altitude_m, std::int64_t nodes,
                                                        const std::function<SurfacePaths()>& make) {
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(surface_, Key{optics.get(), altitude_m, nodes, 0}, make);
}

std::shared_ptr<const SightLines> WorldCache::sight_lines(const std::shared_ptr<const atmosphere::PathOptics>& optics,
                                                          double altitude_m, std::int64_t nodes,
                                                          const std::function<SightLines()>& make) {
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(sight_lines_, Key{optics.get(), altitude_m, nodes, 0}, make);
}

std::shared_ptr<const atmosphere::SunlightTable> WorldCache::sunlight(
    const std::shared_ptr<const atmosphere::PathOptics>& optics, std::int64_t nodes,
    const std::function<atmosphere::SunlightTable()>& make) {
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(sunlight_, Key{optics.get(), 0.0, nodes, 0}, make);
}

std::shared_ptr<const Downwelling> WorldCache::downwelling(const std::shared_ptr<const atmosphere::SunlightTable>& sunlight,
                                                           std::int64_t nodes, std::int64_t sight_line_nodes,
                                                           const std::function<Downwelling()>& make) {
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(downwelling_, Key{sunlight.get(), 0.0, nodes, sight_line_nodes}, make);
}

std::shared_ptr<const std::vector<double>> WorldCache::airglow(
    const std::shared_ptr<const atmosphere::PathOptics>& optics, const std::function<std::vector<double>()>& make) {
  std::lock_guard<std::mutex> lock(mutex_);
  return cached(airglow_, optics.get(), make);
}

namespace {
// Imaging::small_extended (world.hpp): its bounding disc spans fewer than
// kSmallObjectSamples samples, or one of several parts fewer than
// kSmallPartSamples.
bool small_object(const WorldObject& w, double sample_angle_rad) {
  const auto samples = [&](double radius_m) {
    return 2.0 * std::asin(std::min(1.0, radius_m / w.range_m)) / sample_angle_rad;
  };
  if (samples(w.bounding_radius_m) < kSmallObjectSamples) return true;
  if (w.placed.parts.size() < 2) return false;
  for (const geometry::ShapePart& part : w.placed.parts)
    if (samples(geometry::shape_bounding_radius_m(part.geom)) < kSmallPartSamples) return true;
  return false;
}
}  // namespace

std::shared_ptr<const World> build_world(const universe::Universe& universe, const universe::Library& library,
                                         const EngineTime& t, const universe::Object& sensor,
                                         const ViewDefinition& view, WorldCache* cache,
                                         const std::set<std::string>* frame_point_sources) {
  auto world = std::make_shared<World>();
  world->time = t;
  world->sensor_name = sensor.name;
  world->view = view;
  const universe::Kinematics k = universe::kinematics_at(universe, sensor, t);
  world->observer = Observer{k.position_m, k.velocity_m_s, k.attitude.toRotationMatrix()};
  const double half_integration_s = 0.5 * view.integration_time_s;
  const EngineTime start = t.plus_seconds(-half_integration_s), end = t.plus_seconds(half_integration_s);
  {
    const universe::Kinematics k0 = universe::kinematics_at(universe, sensor, start);
    const universe::Kinematics k1 = universe::kinematics_at(universe, sensor, end);
    world->observer.position_start_m = k0.position_m;
    world->observer.position_end_m = k1.position_m;
    world->observer.body_to_j2000_start = k0.attitude.toRotationMatrix();
    world->observer.body_to_j2000_end = k1.attitude.toRotationMatrix();
  }
  frames::Vec3 sun_r, sun_v;
  universe::central_body_state_j2000(universe::central_body_info(universe::CentralBody::sun), t, sun_r, sun_v);
  const radiometry::SpectralBand& band = world->view.spectral.band;
  world->sun.position_m = sun_r - world->observer.position_m;
  world->sun.radius_m = universe::sun_radius_m;
  world->sun.radiance =
      library.spectra.sun().radiance_W_cm2_sr_um.interval_means(band.low_um, band.interval_um(), band.intervals);
  const Mat3 j2000_to_body = world->observer.body_to_j2000.transpose();
  const geometry::SampleGrid& grid = world->view.grid;
  const double sample_angle_rad = grid.sample_angle_rad();
  const Fidelity& f = world->view.fidelity;

  // The Earth's atmosphere, when its central body has it on (spec 4.3.1.1):
  // each object's light reaches the sensor through it (T_out) with the
  // path's own thermal radiance (L_path), and the Sun's reaches the object
  // through it (T_in), at the object's centre; the Earth's surface through
  // the tables of SurfacePaths. The settings and figure are the universe's
  // Earth's, in the world or not (a sensor on the Earth does not image it).
  for (const universe::Object& o : universe.objects()) {
    if (o.kind != ObjectKind::central_body || o.central_body != universe::CentralBody::earth ||
        o.atmosphere.model == universe::AtmosphereModel::none)
      continue;
    WorldAtmosphere& a = world->atmosphere;
    a.settings = o.atmosphere;
    a.optics = cache ? cache->optics(o.atmosphere, library.data_dir, band, f.atmosphere_sub_sample_spacing_cm1,
                                     f.atmosphere_layer_stride)
                     : std::make_shared<const atmosphere::PathOptics>(
                           atmosphere::AtmosphereProfile::make(o.atmosphere, library.data_dir,
                                                               static_cast<std::size_t>(f.atmosphere_layer_stride)),
                           o.atmosphere, library.data_dir, band, f.atmosphere_sub_sample_spacing_cm1);
    a.profile = a.optics->profile_ptr();
    a.earth.centre_m = -world->observer.position_m;  // the Earth at the geocentre, as place() puts it
    a.earth.pole = frames::j2000_to_earth_fixed(t).transpose().col(2);
    a.earth.equatorial_radius_m = o.body.dimensions_m[0];
    a.earth.polar_radius_m = o.body.dimensions_m[1];
    a.observer_inside = atmosphere::altitude_m(a.earth, Vec3::Zero()) < a.profile->top_altitude_m();
    {  // the observer's geodetic vertical and the refraction of its air
      const Vec3 p = -a.earth.centre_m;
      const double z = p.dot(a.earth.pole);
      const Vec3 equatorial = p - z * a.earth.pole;
      a.zenith = (equatorial / (a.earth.equatorial_radius_m * a.earth.equatorial_radius_m) +
                  z * a.earth.pole / (a.earth.polar_radius_m * a.earth.polar_radius_m))
                     .normalized();
      const atmosphere::Densities here = a.profile->at(atmosphere::altitude_m(a.earth, Vec3::Zero()));
      a.refraction = atmosphere::refraction_constants(
          here.pressure_Pa, here.temperature_K,
          atmosphere::relative_humidity_pct(here.h2o_m3, here.temperature_K) / 100.0, 0.5 * (band.low_um + band.high_um));
    }
    // The Sun for single scatter (eq. 6's E = L_tab dOmega above the air).
    if (world->sun.position_m.norm() > 0) {
      a.to_sun = world->sun.position_m.normalized();
      const double omega = universe::sun_projected_solid_angle_sr(world->sun.position_m.norm());
      for (const double L : world->sun.radiance) a.sun_irradiance.push_back(L * omega);
      const atmosphere::EarthFigure figure = a.earth;
      const auto optics = a.optics;
      const int nodes = static_cast<int>(f.atmosphere_sun_nodes);
      const auto make = [optics, figure, nodes] { return atmosphere::SunlightTable(*optics, figure, nodes); };
      a.sunlight = cache ? cache->sunlight(a.optics, nodes, make)
                         : std::make_shared<const atmosphere::SunlightTable>(make());
    }
  }

  // 1. Place and classify (DESIGN section 1, step 2).
  std::vector<const universe::Object*> sources;
  for (const universe::Object& o : universe.objects()) {
    if (o.name == sensor.parent) continue;  // a sensor never images its parent (4.1.5.1)
    std::unique_ptr<WorldObject> w = place(universe, o, t, *world);
    if (!w) continue;
    w->id = static_cast<std::int32_t>(world->objects.size());
    w->world_ = world.get();
    w->placed.object_id = w->id;
    const double range = w->range_m, radius = w->bounding_radius_m;
    // Seen where the refraction raises it (not an object around the observer).
    w->seen = w->placed;
    if (range > radius) {
      w->refraction_fraction = world->atmosphere.refraction_fraction(w->placed.position_m);
      w->seen.position_m = range * world->atmosphere.apparent_direction(w->placed.position_m / range,
                                                                         w->refraction_fraction);
    }
    if (outside_view(j2000_to_body * w->seen.position_m, radius, grid))
      w->imaging = Imaging::outside;
    else if (range > radius && 2.0 * std::asin(std::min(1.0, radius / range)) < sample_angle_rad)
      w->imaging = Imaging::point_source;  // a distant area source smaller than a sample (4.1.6.1)
    else if (!w->central_body && range > radius && small_object(*w, sample_angle_rad))
      w->imaging = Imaging::small_extended;  // its parts may be thinner than a sample
    else
      w->imaging = Imaging::extended;
    if (frame_point_sources && w->imaging != Imaging::outside) {
      // A motion sub-step (scene/motion_substeps.hpp): the frame time's class decides point or not.
      if (frame_point_sources->count(w->name))
        w->imaging = Imaging::point_source;
      else if (w->imaging == Imaging::point_source)
        w->imaging = Imaging::small_extended;
    }
    w->placed.ray_mask = w->imaging == Imaging::extended || w->imaging == Imaging::small_extended
                             ? geometry::ray_mask_extended
                             : geometry::ray_mask_other;
    w->seen.ray_mask = w->placed.ray_mask;
    if (w->imaging == Imaging::point_source && half_integration_s > 0) {
      // Displacement on the grid over the integration: the object's and the
      // sensor's motion and the sensor's rotation (positions as the host pushed them).
      const Vec3 p0 = universe::kinematics_at(universe, o, start.plus_seconds(-w->light_time_s)).position_m -
                      world->observer.position_start_m;
      const Vec3 p1 = universe::kinematics_at(universe, o, end.plus_seconds(-w->light_time_s)).position_m -
                      world->observer.position_end_m;
      double c0 = 0, r0 = 0, c1 = 0, r1 = 0;
      if (grid.sample_of(world->observer.body_to_j2000_start.transpose() * p0, c0, r0) &&
          grid.sample_of(world->observer.body_to_j2000_end.transpose() * p1, c1, r1)) {
        w->streak_columns = c1 - c0;
        w->streak_rows = r1 - r0;
      }
    }
    if (o.kind == ObjectKind::central_body && o.central_body == universe::CentralBody::sun) world->sun.object = w->id;
    world->objects.push_back(std::move(w));
    sources.push_back(&o);
  }

  std::int32_t earth_id = -1;
  for (std::size_t i = 0; i < world->objects.size(); ++i)
    if (sources[i]->kind == ObjectKind::central_body && sources[i]->central_body == universe::CentralBody::earth)
      earth_id = world->objects[i]->id;
  if (world->atmosphere.on() && earth_id >= 0 &&
      world->objects[static_cast<std::size_t>(earth_id)]->imaging != Imaging::outside) {
    const WorldAtmosphere& a = world->atmosphere;
    // (every observer above the atmosphere sees the same paths)
    const double altitude = std::min(atmosphere::altitude_m(a.earth, Vec3::Zero()), a.profile->top_altitude_m() + 1.0);
    const std::int64_t nodes = f.atmosphere_surface_nodes;
    const auto make = [&a, altitude, nodes] { return surface_paths(a, altitude, nodes); };
    world->atmosphere.surface = cache ? cache->surface(a.optics, altitude, nodes, make)
                                      : std::make_shared<const SurfacePaths>(make());
    if (a.settings.downwelling && a.sunlight) {
      const auto optics = a.optics;
      const auto sunlight = a.sunlight;
      const atmosphere::EarthFigure figure = a.earth;
      const int sun_nodes = static_cast<int>(f.atmosphere_downwelling_nodes);
      const int line_nodes = static_cast<int>(f.atmosphere_sight_line_nodes);
      const auto tables = [optics, sunlight, figure, sun_nodes, line_nodes] {
        return Downwelling(*optics, *sunlight, figure, sun_nodes, line_nodes);
      };
      world->atmosphere.downwelling = cache ? cache->downwelling(a.sunlight, sun_nodes, line_nodes, tables)
                                            : std::make_shared<const Downwelling>(tables());
    }
    world->objects[static_cast<std::size_t>(earth_id)]->under_atmosphere_ = true;
  }
  if (world->atmosphere.on())
    for (const auto& wp : world->objects) {
      WorldObject& w = *wp;
      if (w.id == earth_id) continue;
      std::vector<double> out, path, scatter;
      world->atmosphere.seen_from(w.placed.position_m, out, path, scatter);
      if (!out.empty()) {
        for (std::size_t i = 0; i < path.size(); ++i) path[i] += scatter[i];
        w.path_radiance_W_cm2_sr_ = world->view.spectral.integrate(path);
        w.path_spectral_ = std::move(path);
        w.path_scatter_ = std::move(scatter);
        w.seen_through_ = std::make_unique<radiometry::SpectralView>(
            radiometry::SpectralView::through(world->view.spectral, std::move(out)));
      }
      if (w.id != world->sun.object)
        w.sun_transmittance_ = world->atmosphere.to_space(
            w.placed.position_m, (world->sun.position_m - w.placed.position_m).normalized());
    }

  // 2. What may shade what: every other body, for the Sun and each source.
  std::vector<geometry::Occulter> occulters;
  for (const auto& w : world->objects) occulters.push_back(occulter_of(*w));
  // by_parts: the Sun's vehicles go there, shading by their parts (sun_fraction).
  auto candidates = [&](const WorldObject& receiver, const Vec3& light, double light_radius, std::int32_t light_object,
                        std::vector<const WorldObject*>* by_parts = nullptr) {
    std::vector<geometry::Occulter> out;
    for (const auto& w : world->objects)
      if (w->id != receiver.id && w->id != light_object &&
          can_shade(receiver.placed.position_m, receiver.bounding_radius_m, light, light_radius,
                    occulters[static_cast<std::size_t>(w->id)])) {
        if (by_parts && shades_by_parts(w->kind)) by_parts->push_back(w.get());
        else out.push_back(occulters[static_cast<std::size_t>(w->id)]);
      }
    return out;
  };
  for (const auto& w : world->objects)
    w->occulters_.push_back(
        candidates(*w, world->sun.position_m, world->sun.radius_m, world->sun.object, &w->part_shadows_));

  // 3. Surfaces: materials through the view, temperatures (spec 4.3.1.3).
  WorldBuilder builder(*world, library);
  for (std::size_t i = 0; i < world->objects.size(); ++i) {
    WorldObject& w = *world->objects[i];
    const universe::Object& o = *sources[i];
    const std::vector<universe::ShapePart> shape = universe::shape_parts_at(o, t);
    ThermalField thermal;
    if (o.body.thermal_model == universe::ThermalModel::subsolar) {
      thermal.subsolar = true;
      thermal.subsolar_K = o.body.subsolar_temperature_K;
      thermal.night_K = o.body.night_temperature_K;
      thermal.sun_body = (w.placed.body_to_frame.transpose() * (sun_r - w.geocentric_position_m)).normalized();
      if (w.central_body) {  // spin axis: the body frame's z (the IAU pole)
        thermal.airless_night = true;
        thermal.solar_day_s = universe::central_body_info(o.central_body).solar_day_s;
        thermal.spin_axis_body = Vec3::UnitZ();
      }
    }
    // Thermal model eclipse: radiative equilibrium with the visible fraction
    // f of the solar disc, T^4 = T_e^4 + f (T_sunlit^4 - T_e^4) (memoryless).
    const bool eclipse = o.body.thermal_model == universe::ThermalModel::eclipse;
    const double fraction = eclipse ? w.sun_fraction(w.placed.position_m) : 1.0;
    const double te4 = std::pow(o.body.eclipse_temperature_K, 4.0);
    std::vector<PartSurface> parts;
    for (std::size_t p = 0; p < shape.size(); ++p) {
      const std::string field = o.body.shape == universe::ShapeKind::composite
                                    ? o.name + ".composite[" + std::to_string(p) + "].material"
                                    : o.name + ".material";
      double T = shape[p].temperature_K.value_or(o.body.temperature_K);
      if (eclipse && shape[p].kind != universe::ShapeKind::plume)  // (a plume keeps its temperature)
        T = std::pow(te4 + fraction * (std::pow(T, 4.0) - te4), 0.25);
      parts.push_back(PartSurface{builder.spectrum(shape[p].material.value_or(o.body.material),
                                                   shape[p].reflectance.value_or(o.body.reflectance), field, w.view()),
                                  T,
                                  shape[p].spectrum ? builder.self_radiance(*shape[p].spectrum, o.name + ".missile_stages")
                                                    : std::vector<double>{},
                                  shape[p].kind == universe::ShapeKind::plume});
    }
    Geography geography;
    if (w.central_body) {
      geography.equatorial_radius_m = w.equatorial_radius_m;
      geography.polar_radius_m = w.polar_radius_m;
      geography.geodetic = o.central_body == universe::CentralBody::earth;
      // Maps at the level the ground sample distance asks for (spec 4.2.3).
      const double gsd_m = std::max(w.range_m - w.equatorial_radius_m, 1.0) * sample_angle_rad;
      if (const universe::BodyMaps* maps = library.maps_of(o.central_body)) {
        if (f.scene_mode == SceneMode::bitmap && maps->land_cover) {
          geography.land_cover = &maps->land_cover->level_for(gsd_m, w.equatorial_radius_m);
          geography.class_spectra.assign(19, nullptr);
          for (int c = 1; c <= 18; ++c) {
            char prefix[16];
            std::snprintf(prefix, sizeof prefix, "igbp_%02d_", c);
            for (const std::string& name : library.materials.names())
              if (name.rfind(prefix, 0) == 0)
                geography.class_spectra[static_cast<std::size_t>(c)] =
                    builder.spectrum(name, 0.0, o.name + ".bitmap", w.view());
          }
          if (maps->land_brightness) geography.land_brightness = &maps->land_brightness->finest();
        }
        if (f.scene_mode == SceneMode::bitmap && maps->albedo) {
          const universe::RasterLevel& level = maps->albedo->level_for(gsd_m, w.equatorial_radius_m);
          geography.albedo = &level;
          for (int v = 0; v < 256; ++v)
            geography.albedo_spectra.push_back(builder.spectrum(
                universe::central_body_surface(o.central_body).albedo_map_material,
                std::clamp(level.value_offset() + level.value_scale() * v, 0.0, 1.0), o.name + ".bitmap", w.view()));
        }
        if (o.body.thermal_model == universe::ThermalModel::climatology && maps->land_mask) {
          geography.land_mask = &maps->land_mask->level_for(gsd_m, w.equatorial_radius_m);
          geography.climatology = library.climatology.get();
          geography.climatology_now = ClimatologyInstant(*geography.climatology, calendar_instant(t));
        }
      }
      if (o.clouds.enabled) {  // (the property refuses every body but the Earth)
        const universe::BodyMaps* maps = library.maps_of(o.central_body);
        if (!maps || !maps->clouds)
          throw Error(Status::io, o.name + ".clouds: the data folder has no cloud map (earth/clouds_L0.json; "
                                           "data/earth/README.md)");
        geography.clouds = &maps->clouds->finest();
        geography.cloud_spectrum =
            builder.own(cloud_top_material(library.materials, o.clouds.reflectance, o.name + ".clouds"), w.view());
        geography.cloud_height_m = 1e3 * o.clouds.top_altitude_km;
        geography.cloud_temperature_K = o.clouds.top_temperature_K;
      }
      if (o.body.thermal_model == universe::ThermalModel::climatology && !geography.climatology)
        throw Error(Status::not_allowed, o.name + ".thermal_model: climatology is the Earth's (land and water tables)");
    }
    w.surface = std::make_unique<SurfaceModel>(std::move(parts), thermal,
                                               builder.self_radiance(o.body.spectrum, o.name + ".spectrum"),
                                               std::move(geography), w.view(),
                                               f.scene_mode == SceneMode::smooth ? f.temperature_table_size : 0);
  }

  // The emission of the Earth's materials through its paths (PathEmission).
  if (world->atmosphere.surface) {
    world->atmosphere.black_emission = world->atmosphere.surface->emission(
        world->view.spectral, std::vector<double>(world->view.spectral.sample_wavelengths_um.size(), 1.0));
    for (const auto& spectrum : world->spectra) {
      std::vector<double> weights;
      double scale = 1;
      if (spectrum->emissivity(weights, scale))
        world->atmosphere.surface_emission[spectrum.get()] =
            WorldAtmosphere::SurfaceEmission{world->atmosphere.surface->emission(world->view.spectral, weights), scale};
    }
  }

  // 4. Every object but the Sun as a light source (eq. 7; eq. 8 where large).
  for (const auto& wp : world->objects) {
    WorldObject& w = *wp;
    if (w.id == world->sun.object) continue;
    ObjectLight light;
    light.object = w.id;
    light.position_m = w.placed.position_m;
    light.radius_m = w.volumetric_radius_m;
    light.bounding_radius_m = w.bounding_radius_m;
    light.area_source = true;
    light.to_sun = (world->sun.position_m - light.position_m).normalized();
    w.light_ = static_cast<std::int32_t>(world->lights.size());
    world->lights.push_back(std::move(light));
  }
  // A source whose eq. 7 light cannot reach kNegligible of a receiver's
  // coldest self-emission anywhere on it is left out there (a 1 m satellite
  // 700 km above the Earth in 8-12 um: ~1e-11). Its bound: the greatest
  // dOmega = pi (R / d)^2 (d from the receiver's bounding sphere), times
  // SRF x BRDF x cos(incidence) at most, times at most its band radiance:
  // E_sun SRF 2 / (3 pi) (Phase <= 1, the whole Sun) plus twice its
  // emission bound (the band rule of light_spectra's sum may differ from
  // emission_radiance's; light_spectra itself can cost a sum over 1e5
  // patches, which a frame may never need). Only where eq. 7, not eq. 8,
  // serves it. With object limits above the default profile (README "Object
  // limits": the GEO belt's hundreds of satellites), also where its
  // irradiance dOmega x radiance cannot reach kNegligible of the Sun's at
  // the receiver (L_sun dOmega_sun: a 2 m satellite 100 km away, ~1e-11).
  const double sun_band_radiance = world->view.spectral.integrate(world->sun.radiance);
  const bool many_objects = !universe.limits().is_default();
  std::vector<double> light_radiance(world->lights.size());  // each source's band radiance bound
  for (std::size_t j = 0; j < world->lights.size(); ++j) {
    const ObjectLight& light = world->lights[j];
    const SurfaceModel& source = *world->objects[static_cast<std::size_t>(light.object)]->surface;
    const double sun_omega = universe::sun_projected_solid_angle_sr((world->sun.position_m - light.position_m).norm());
    light_radiance[j] =
        source.srf_bound() * sun_band_radiance * sun_omega * 2.0 / (3.0 * constants::pi) + 2.0 * source.emission_bound();
  }
  for (const auto& w : world->objects) {
    w->negligible_light_.assign(world->lights.size(), 0);
    const double floor = w->surface->emission_floor(), reflection = w->surface->reflection_bound_per_sr();
    const bool against_emission = floor > 0 && std::isfinite(reflection) && w->surface->reflects();
    const double sunlight =
        universe::sun_projected_solid_angle_sr((world->sun.position_m - w->placed.position_m).norm()) *
        sun_band_radiance;
    // (sunlight reflected at its brightest cannot make the emission negligible)
    w->emission_first_ = !(reflection * sunlight > w->surface->emission_bound() / kNegligible);
    if (!against_emission && !many_objects) continue;
    for (std::size_t j = 0; j < world->lights.size(); ++j) {
      const ObjectLight& light = world->lights[j];
      if (light.object == w->id) continue;
      const double d = (light.position_m - w->placed.position_m).norm() - w->bounding_radius_m;
      if (!(d > light.radius_m)) continue;
      const double omega = constants::pi * (light.radius_m / d) * (light.radius_m / d);
      if (light.area_source && omega > f.area_source_solid_angle_sr) continue;
      const double radiance = light_radiance[j];
      w->negligible_light_[j] = (against_emission && omega * reflection * radiance < kNegligible * floor) ||
                                (many_objects && omega * radiance < kNegligible * sunlight);
    }
  }
  // What may shade each light that counts at a receiver (a negligible one's
  // occulters are never asked for: none kept).
  for (const auto& w : world->objects)
    for (std::size_t j = 0; j < world->lights.size(); ++j) {
      const ObjectLight& light = world->lights[j];
      w->occulters_.push_back(w->negligible_light_[j] ? std::vector<geometry::Occulter>{}
                                                      : candidates(*w, light.position_m, light.radius_m, light.object));
    }

  std::vector<const geometry::PlacedObject*> cast_against;
  for (const auto& w : world->objects) cast_against.push_back(&w->seen);
  world->caster.build(cast_against);

  // 5. The sky, if the universe has a star field, and under the atmosphere
  // its light over the view.
  for (const universe::Object& o : universe.objects())
    if (o.kind == ObjectKind::star_field) {
      build_sky(*world, o, library);
      break;
    }
  if (world->atmosphere.sunlight) {
    WorldAtmosphere& a = world->atmosphere;
    const double altitude = std::min(atmosphere::altitude_m(a.earth, Vec3::Zero()), a.profile->top_altitude_m());
    const atmosphere::EarthFigure figure = a.earth;
    const auto optics = a.optics;
    const int nodes = static_cast<int>(f.atmosphere_sight_line_nodes);
    const auto make = [optics, figure, altitude, nodes] { return SightLines::make(*optics, figure, altitude, nodes); };
    const auto lines =
        cache ? cache->sight_lines(a.optics, altitude, nodes, make) : std::make_shared<const SightLines>(make());
    const auto azimuths = static_cast<std::size_t>(f.atmosphere_sky_azimuths);
    std::vector<double> background;
    if (world->sky.background)
      for (const double E : world->sky.background_irradiance) background.push_back(E / constants::pi);
    std::vector<double> airglow;  // the night airglow's zenith radiance (atmosphere/airglow.hpp)
    if (a.settings.airglow) {
      const radiometry::SpectralBand b = a.optics->band();
      const std::string dir = library.data_dir;
      const auto zenith = [dir, b] {
        return atmosphere::Airglow::load(dir).zenith_radiance(b.low_um, b.interval_um(), b.intervals);
      };
      airglow = cache ? *cache->airglow(a.optics, zenith) : zenith();
    }
    a.sky = std::make_shared<const SkyView>(lines, a.sunlight, a.earth, a.to_sun, a.sun_irradiance, background,
                                            airglow, world->view.spectral, azimuths);
    // Moonlight scattered by the air over an observer inside it: the Moon's
    // irradiance above the air as eq. 7 gives it (its disc, phase law and
    // emission), from the Moon's direction.
    const WorldObject* moon = nullptr;
    for (const auto& o : world->objects)
      if (o->central_body && o->name == "Moon" && o->light_ >= 0) moon = o.get();
    if (moon && a.observer_inside) {
      const LightSpectra& light = moon->light_spectra();
      const Vec3 to_moon = moon->placed.position_m / moon->range_m;
      const double omega = constants::pi * std::pow(moon->volumetric_radius_m / moon->range_m, 2.0);
      const double phase =
          moon->disk_photometry.phase(world->lights[static_cast<std::size_t>(moon->light_)].to_sun.dot(-to_moon));
      std::vector<double> E(light.reflected.size());
      for (std::size_t i = 0; i < E.size(); ++i) E[i] = (light.reflected[i] * phase + light.emitted[i]) * omega;
      a.moon_sky = std::make_shared<const SkyView>(lines, a.sunlight, a.earth, to_moon, E, std::vector<double>{},
                                                   std::vector<double>{}, world->view.spectral, azimuths);
    }
  }
  return world;
}

}  // namespace eoir::scene
