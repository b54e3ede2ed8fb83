// The world: an immutable, typed snapshot of the modeled universe for one
// (sensor, time) (DESIGN section 1, steps 1-2). Observer kinematics; every
// object placed relative to the observer in double precision, culled and
// classified once (outside the view, imaged as an extended area source, or
// a distant area source smaller than a sample, spec 4.1.6.1); its shape
// parts, its tessellation (made on first use) and its surface model; the
// light sources (the Sun and every object, spec 4.1.5.3); and one committed
// ray caster. Everything that looks at the universe at that instant -- the
// image, target metrics, per-frame truth, picks -- reads this world and
// builds no other. It copies what it needs, so it stays valid after the
// universe changes.
#pragma once
#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "atmosphere/path_optics.hpp"
#include "atmosphere/profile.hpp"
#include "atmosphere/refraction.hpp"
#include "atmosphere/shell_path.hpp"
#include "core/fidelity.hpp"
#include "core/once.hpp"
#include "core/time.hpp"
#include "geometry/eclipse.hpp"
#include "geometry/sample_grid.hpp"
#include "geometry/scene_geometry.hpp"
#include "radiometry/spectral_view.hpp"
#include "scene/downwelling.hpp"
#include "scene/light_environment.hpp"
#include "scene/sight_lines.hpp"
#include "scene/sky.hpp"
#include "scene/surface_model.hpp"
#include "universe/library.hpp"
#include "universe/universe.hpp"

namespace eoir::scene {

using Mat3 = Eigen::Matrix3d;

// How the sensor's scene generator images an object (spec 4.1.3, 4.1.6.1).
enum class Imaging : int {
  outside = 0,       // wholly outside the view frustum (field plus guard band): culled
  extended = 1,      // resolved: ray-cast on the sample grid
  point_source = 2,  // smaller than a sample: kept apart at its focal-plane position
  // resolved, but few samples across (kSmallObjectSamples) or with parts
  // that are (kSmallPartSamples): a sample is too coarse for it, so the
  // samples it reaches take its light from a finer window of rays
  // (WorldObject::window; scene/scene_generator.cpp)
  small_extended = 3,
};

// Objects (not central bodies) whose bounding disc spans fewer scene samples
// than kSmallObjectSamples, or one of whose several parts spans fewer than
// kSmallPartSamples, are imaged as Imaging::small_extended.
constexpr double kSmallObjectSamples = 64.0;
constexpr double kSmallPartSamples = 8.0;
// Rays across an object's bounding disc in the window of its detailed sum
// (each axis).
constexpr std::int64_t kVisibleWindowRays = 128;

// An object seen through a fine window of rays from the observer across its
// bounding disc (the spec's "tessellations that are visible to the
// observer", 4.1.6.1): each ray that meets the object before anything else
// carries its patch and its solid angle, so the patch's visible projected
// solid angle is the sum of its rays'.
struct VisibleWindow {
  struct Ray {
    Vec3 direction;            // unit, observer frame (J2000 axes)
    std::int32_t patch = 0;    // in the object's tessellation
    double solid_angle_sr = 0;
    std::int32_t part = 0;     // where it meets the object: part, point and outward normal (body frame)
    Vec3 point_body_m = Vec3::Zero(), normal_body = Vec3::UnitZ();
    std::int32_t facet = -1;   // the mesh triangle it meets (geometry::Hit::facet)
  };
  std::vector<Ray> rays;                 // those meeting the object
  std::vector<double> patch_solid_angle_sr;  // per patch: its visible projected solid angle
};

// What the sensor defines for the scene generator: its sample grid and
// spectral view (the sensor model resolves them), and its fidelity knobs.
struct ViewDefinition {
  geometry::SampleGrid grid;
  radiometry::SpectralView spectral;
  Fidelity fidelity;
  double integration_time_s = 0;  // point sources streak over it (centred on the frame time)
};

struct Observer {
  Vec3 position_m = Vec3::Zero();    // geocentric J2000
  Vec3 velocity_m_s = Vec3::Zero();  // J2000
  Mat3 body_to_j2000 = Mat3::Identity();
  // At the start and the end of the integration (frame time -/+ half of it).
  Vec3 position_start_m = Vec3::Zero(), position_end_m = Vec3::Zero();
  Mat3 body_to_j2000_start = Mat3::Identity(), body_to_j2000_end = Mat3::Identity();
};

// The Sun as the light of eq. 6.
struct SunLight {
  Vec3 position_m = Vec3::Zero();  // relative to the observer, J2000 axes
  double radius_m = 0.0;
  std::vector<double> radiance;    // L_tab as interval means on the view (W cm^-2 sr^-1 um^-1)
  std::int32_t object = -1;        // the Sun's world object, if it is in the world
};

// The atmosphere over the Earth's surface as a world sees it: per
// spectral interval, eq. 9's T_out and L_path between a surface point and
// the observer against the cosine of the view's zenith angle there, and
// T_in of the Sun's light against the cosine of the Sun's (spherical
// symmetry: for an observer at a given altitude these angles fix the
// paths), on nodes dense toward the horizon (mu = (k / (n - 1))^2),
// linear between them.
// Eq. 9's terms of one line of sight per interval of the view (spec
// 4.1.5.3; the components of 6.2.5.4): what leaves the surface (eq. 9's
// bracket: reflected light, DownWelling and emission; for the sky, the
// background light), of which DownWelling / pi x SRF, the path's
// transmittance T_out, its thermal radiance L_path and the sunlight its
// air scatters L_scatter; at the sensor: surface x T_out + L_path +
// L_scatter. In vacuum T_out is 1 and the path's terms 0.
struct Eq9Terms {
  std::vector<double> surface, downwelling, transmittance, path_thermal, path_scatter, at_sensor;
};

class PathEmission;
struct SurfacePaths {
  std::vector<double> mu;                      // nodes, 0..1
  std::vector<std::vector<double>> view_T, view_L, sun_T;  // [node][interval]
  bool empty() const { return mu.empty(); }
  // Interpolated at mu (clamped to [0, 1]) into out.
  void view_at(double mu_view, std::vector<double>& T, std::vector<double>& L) const;
  void sun_at(double mu_sun, std::vector<double>& T) const;
  // The emission through these paths of a surface of emissivity `weights`
  // on the view's grid (PathEmission), made on first use and kept with the
  // paths (thread-safe), so that every frame of an engine shares it.
  std::shared_ptr<const PathEmission> emission(const radiometry::SpectralView& view,
                                               const std::vector<double>& weights) const;
  struct EmissionCache {
    std::mutex mutex;
    std::map<std::vector<double>, std::shared_ptr<const PathEmission>> tables;  // key: weights, then wavelengths
  };
  std::shared_ptr<EmissionCache> emission_cache = std::make_shared<EmissionCache>();
};

// Eq. 9's self-emission term through a surface point's path, sum_i
// T_out,i(mu) eps_i B_i(T) dlambda (eq. 48 of the emission times T_out),
// for one emissivity on the view's grid: per node of SurfacePaths an L(T)
// table (radiometry/band_planck_table.hpp) of weights eps_i T_out,i,
// blended in mu with view_at's weights. That is the per-interval sum with
// view_at's T_out (T_out is linear in mu between nodes, so is the sum) within
// the tables' 3e-13 relative, for two exps per sample instead of a Planck
// term per interval (issue 20 item 8).
class PathEmission {
 public:
  PathEmission(const SurfacePaths& paths, const radiometry::SpectralView& view, const std::vector<double>& weights);
  // W cm^-2 sr^-1, at the view's zenith cosine mu (clamped to [0, 1]).
  double radiance(double mu_view, double temperature_K) const;

 private:
  std::vector<double> mu_;
  std::vector<std::unique_ptr<radiometry::BandPlanckTable>> tables_;  // per node; null: T_out eps 0 throughout
};

// The Earth's atmosphere in the world (spec 4.3.1.1, DESIGN "The atmosphere
// in the world"): its state, made when the Earth's `atmosphere` is on, and
// the Earth's figure relative to the observer (J2000 axes) for the paths.
struct WorldAtmosphere {
  universe::AtmosphereSettings settings;
  std::shared_ptr<const atmosphere::AtmosphereProfile> profile;  // null: vacuum
  std::shared_ptr<const atmosphere::PathOptics> optics;           // on the view's band
  atmosphere::EarthFigure earth;
  bool observer_inside = false;  // the observer lies below the top of the atmosphere
  bool on() const { return profile != nullptr; }
  // Eq. 9's path terms per interval between a point and the observer: the
  // transmittance, and the path's radiance toward the observer: its thermal
  // emission (L_path) and the sunlight its air scatters (L_scatter); empty
  // in vacuum.
  void seen_from(const Vec3& point_m, std::vector<double>& transmittance, std::vector<double>& thermal,
                 std::vector<double>& scatter) const;
  // The transmittance per interval of the view from a point toward space
  // along a unit direction (toward the Sun, a star); empty where the path
  // crosses no air. A path from an observer inside the atmosphere to space
  // follows the refracted ray.
  std::vector<double> to_space(const Vec3& point_m, const Vec3& direction) const;
  // The path from the observer to a point, its segments from the observer
  // out (refracted from an observer inside the atmosphere to a point above
  // it; empty in vacuum).
  atmosphere::PathColumns path_to(const Vec3& point_m) const;
  // The air of a path, and toward space along a direction from the
  // observer, in sea-level vertical columns (spec 6.2.5.4: straight up from
  // the ground is 1); 0 in vacuum.
  double air_mass(const atmosphere::PathColumns& path) const;
  double air_mass_toward(const Vec3& direction) const;
  // Where a source in the (true, unit) direction d appears to an observer
  // inside the atmosphere: raised toward the zenith by the refraction
  // (atmosphere/refraction.hpp); d itself for an observer above it or in
  // vacuum. A point at a finite distance is raised by `fraction` of it
  // (refraction_fraction).
  Vec3 apparent_direction(const Vec3& d, double fraction = 1.0) const;
  // The share of the refraction of a source at infinity in its direction
  // that a point at its distance shows (atmosphere::chord_refraction): 1 for
  // the stars, a little less for a satellite (the bent ray's parallax),
  // about k D / (2 R_E) over the full refraction for an aircraft D away; 0
  // where nothing is refracted.
  double refraction_fraction(const Vec3& point_m) const;
  Vec3 zenith = Vec3::UnitZ();                      // the observer's geodetic vertical (J2000)
  atmosphere::RefractionConstants refraction;       // at the observer, at the band's centre wavelength
  std::shared_ptr<const SurfacePaths> surface;      // over the Earth's surface (when it is imaged)
  // Single scatter: T_sun over (altitude, Sun angle), the Sun (unit
  // direction, irradiance per interval above the air), and the sky's terms
  // over this frame's lines of sight.
  std::shared_ptr<const atmosphere::SunlightTable> sunlight;
  Vec3 to_sun = Vec3::UnitX();
  std::vector<double> sun_irradiance;
  std::shared_ptr<const SkyView> sky;
  std::shared_ptr<const SkyView> moon_sky;  // moonlight's scatter over an observer inside the atmosphere
  // Eq. 9's L_scatter along the line of sight d from the observer: the
  // Sun's and the Moon's (band; per interval added into out).
  double scatter_band(const Vec3& d) const;
  void add_scatter(const Vec3& d, std::vector<double>& out) const;
  std::shared_ptr<const Downwelling> downwelling;  // on the Earth's surface, when the setting has it
  // Per material of the world (grid integration), its emission through
  // `surface` (PathEmission) and the scale of its emissivity (a gray
  // body's eps; its table is the black body's).
  struct SurfaceEmission {
    std::shared_ptr<const PathEmission> table;
    double scale = 1.0;
  };
  std::unordered_map<const SurfaceSpectrum*, SurfaceEmission> surface_emission;
  // A black body's (the share 1 - s of land whose SRF the land's brightness
  // scales by s emits as one: SurfaceModel::add_emission).
  std::shared_ptr<const PathEmission> black_emission;
};

// What the worlds of one engine build once and share (thread-safe): the
// atmosphere's path optics per setting, band and sub-sample spacing, and
// its tables per observer altitude (clamped at the top of the atmosphere,
// so that every observer above it shares one) and table size (the
// fidelity's atmosphere knobs). Owned by the engine.
class WorldCache {
 public:
  std::shared_ptr<const atmosphere::PathOptics> optics(const universe::AtmosphereSettings& settings,
                                                       const std::string& data_dir,
                                                       const radiometry::SpectralBand& band,
                                                       double sub_sample_spacing_cm1 = atmosphere::kSubSampleSpacing_cm1,
                                                       std::int64_t layer_stride = 1);
  // The tables of `optics` for an observer at that (clamped) altitude with
  // that many nodes (and, for DownWelling, the sight lines' nodes), made by
  // `make` if new.
  std::shared_ptr<const SurfacePaths> surface(const std::shared_ptr<const atmosphere::PathOptics>& optics,
                                              double altitude_m, std::int64_t nodes,
                                              const std::function<SurfacePaths()>& make);
  std::shared_ptr<const SightLines> sight_lines(const std::shared_ptr<const atmosphere::PathOptics>& optics,
                                                double altitude_m, std::int64_t nodes,
                                                const std::function<SightLines()>& make);
  std::shared_ptr<const atmosphere::SunlightTable> sunlight(const std::shared_ptr<const atmosphere::PathOptics>& optics,
                                                            std::int64_t nodes,
                                                            const std::function<atmosphere::SunlightTable()>& make);
  std::shared_ptr<const Downwelling> downwelling(const std::shared_ptr<const atmosphere::SunlightTable>& sunlight,
                                                 std::int64_t nodes, std::int64_t sight_line_nodes,
                                                 const std::function<Downwelling()>& make);
  // The airglow's zenith radiance per interval of the optics' band.
  std::shared_ptr<const std::vector<double>> airglow(const std::shared_ptr<const atmosphere::PathOptics>& optics,
                                                     const std::function<std::vector<double>()>& make);

 private:
  using Key = std::tuple<const void*, double, std::int64_t, std::int64_t>;
  std::mutex mutex_;
  std::vector<std::tuple<universe::AtmosphereSettings, std::string, double, double, std::int64_t, double,
                         std::int64_t, std::shared_ptr<const atmosphere::PathOptics>>>
      optics_;
  std::map<Key, std::shared_ptr<const SurfacePaths>> surface_;
  std::map<Key, std::shared_ptr<const SightLines>> sight_lines_;
  std::map<Key, std::shared_ptr<const atmosphere::SunlightTable>> sunlight_;
  std::map<Key, std::shared_ptr<const Downwelling>> downwelling_;
  std::map<const atmosphere::PathOptics*, std::shared_ptr<const std::vector<double>>> airglow_;
};

class World;
class WorldObject;

// The bodies that may shade the lights of a receiver at the points of a
// small region of it (a tile of samples: WorldObject::shadow_casters_near),
// laid out as its own lists: per light (0 the Sun, 1 + k lights[k]) the
// occulters, and the vehicles that shade by their parts. Those left out hide
// nothing of any light anywhere in the region, so results are unchanged.
struct ShadowCasters {
  std::vector<std::vector<geometry::Occulter>> occulters;
  std::vector<const WorldObject*> part_shadows;
  // The region they were found for (observer frame, m).
  Vec3 centre_frame_m = Vec3::Zero();
  double radius_m = 0.0;
};

class WorldObject {
 public:
  std::int32_t id = 0;  // index in World::objects, the ray caster's object_id
  std::string name;
  universe::ObjectKind kind = universe::ObjectKind::satellite;
  bool central_body = false;  // a background, not a target (per-frame truth)
  double equatorial_radius_m = 0, polar_radius_m = 0;  // central bodies: for latitude/longitude and eclipses
  geometry::PlacedObject placed;  // parts, position relative to the observer (J2000 axes), body frame
  // Where the observer's rays meet it (the ray caster's): `placed`, raised
  // by the refraction for an observer inside the atmosphere
  // (WorldAtmosphere::apparent_direction); light and shadow use `placed`.
  geometry::PlacedObject seen;
  double refraction_fraction = 0;  // WorldAtmosphere::refraction_fraction of its centre
  Vec3 geocentric_position_m = Vec3::Zero();  // J2000
  double range_m = 0;             // observer to body origin
  double bounding_radius_m = 0;   // sphere about the body origin enclosing every part
  double volumetric_radius_m = 0; // the sphere of equal volume (eq. 7; plates: of equal area)
  radiometry::DiskPhotometry disk_photometry;  // its disc as a point (eq. 7): Lambertian, or a natural body's law
  Imaging imaging = Imaging::outside;
  bool detailed_point_source = true;  // spec 4.1.6.1: detailed or simple
  // Its parts hide one another in the detailed point-source sum (a missile's
  // stages and plumes, spec 4.1.6.1): a patch inside another part, or whose
  // line toward the observer meets another part, is left out.
  bool parts_hide_each_other = false;
  double light_time_s = 0;        // the Moon and the planets: seen where they were (apparent place)
  double streak_columns = 0, streak_rows = 0;  // point sources: displacement on the grid over the integration
  double patch_size_m = 0;        // target edge of the tessellation's patches
  std::unique_ptr<SurfaceModel> surface;

  // The patches dA (spec 4.1.5.2), made on first use (thread-safe).
  const geometry::Tessellation& tessellation() const;
  // Outward unit normal (body frame) of `part` at a surface point.
  Vec3 normal_at(std::int32_t part, const Vec3& point_body_m) const;
  Vec3 to_frame(const Vec3& point_body_m) const { return placed.position_m + placed.body_to_frame * point_body_m; }
  // A direction (a hit's normal_frame) from the observer frame to the body frame.
  Vec3 direction_to_body(const Vec3& direction_frame) const { return placed.body_to_frame.transpose() * direction_frame; }
  // Unit vector from the object toward the observer, body frame.
  Vec3 toward_observer_body() const;

  // The spectral radiance (eq. 4, W cm^-2 sr^-1 um^-1 at the view's
  // wavelengths) leaving the point of `part` with outward normal normal_body
  // toward the unit direction `toward` (observer frame). sun_only: lit by the
  // Sun alone (the single bounce of light that other objects reflect).
  std::vector<double> spectral_radiance(std::int32_t part, const Vec3& point_body_m, const Vec3& normal_body,
                                        const Vec3& toward, bool sun_only = false) const;
  // Its band integral (eq. 48) toward the observer; emission through the
  // L(T) table when `interpolated`.
  // `near`: the shadow casters of the point's region (shadow_casters_near),
  // or null for all of this object's; `surface_point`: surface->at of the
  // point if made already, or null.
  double effective_radiance(std::int32_t part, const Vec3& point_body_m, const Vec3& normal_body,
                            bool interpolated = false, const ShadowCasters* near = nullptr,
                            const SurfacePoint* surface_point = nullptr) const;
  // effective_radiance(site, interpolated, near, point) of many located
  // points (surface->at's) of a region with shadow casters `near`: the
  // emission's temperatures taken together.
  void effective_radiances(const SurfacePoint* const* points, std::size_t n, const ShadowCasters* near, double* out,
                           bool interpolated = true) const;
  // The effective radiance a sample ending at point_body_m on `part`, with
  // the outward normal hit_normal_body there (the ray caster's), sees, as the
  // scene mode says (spec 4.2): a part's value for plain surfaces; the value
  // at the centre of the point's patch in coarse mode (computed once per
  // patch); the point's own in smooth mode. `facet`: the mesh triangle the
  // ray caster hit (Hit::facet; -1 for analytic shapes), whose patch it is.
  double radiance_at(std::int32_t part, const Vec3& point_body_m, const Vec3& hit_normal_body,
                     std::int32_t facet = -1) const;
  // Of the bodies that may shade this object's lights (its occulters and
  // part shadows), those that may shade them at some point within radius_m
  // of centre_frame_m (observer frame), or of a reflecting layer above it,
  // into `out`.
  void shadow_casters_near(const Vec3& centre_frame_m, double radius_m, ShadowCasters& out) const;
  // Per lights[k]: 1 where its eq. 7 light, reflected by any of the
  // surface's BRDFs, cannot reach negligible_W_cm2_sr anywhere in `near`'s
  // region (its layers' height included; out: lights.size() flags).
  void lights_negligible_in(const ShadowCasters& near, double negligible_W_cm2_sr, std::vector<char>& out) const;
  // radiance_at shades each sample's own point (not coarse mode's patches).
  bool shades_each_sample() const;
  // The point and normal at which that radiance is evaluated (the patch
  // centre and its normal in coarse mode, the point itself and the hit's
  // normal in smooth mode).
  void shading_point(std::int32_t part, const Vec3& point_body_m, const Vec3& hit_normal_body, Vec3& shade_point_body,
                     Vec3& normal_body, std::int32_t facet = -1) const;
  // The radiance of patch k at its centre toward the observer (cached).
  double patch_radiance(std::int32_t patch) const;
  // Projected area A*_T facing the observer (eq. 58, m^2): exact for a single
  // sphere, oblate, box, plate or cylinder, else the sum over patches.
  double projected_area_m2() const;
  // Band-integrated irradiance at the observer of the object seen as a point
  // (spec 4.1.6.1): detailed, the sum over visible patches of L dOmega (ERRATA
  // eq. 11: for one part, its facing patches' cos A dA / R^2, or L A* / R^2
  // for a plain shape; for several, that may hide each other, each patch's
  // visible projected solid angle in visible_window); simple, eq. 7 toward
  // the observer.
  double point_irradiance_W_cm2() const;
  // The window of its detailed sum: kVisibleWindowRays across it
  // (VisibleWindow), made on first use (thread-safe).
  const VisibleWindow& visible_window() const;
  // A window of rays_across rays across it, cast on `threads` workers.
  VisibleWindow window(std::int64_t rays_across, unsigned threads) const;
  // The detailed sum on a tessellation of another patch edge (uncached): how
  // the sum converges with the patch size (scene/adaptive_fidelity.hpp).
  double detailed_point_irradiance_W_cm2(double patch_edge_m) const;
  // Its spectral vector at the sensor (W cm^-2 um^-1; T_out applied).
  std::vector<double> point_spectral_irradiance() const;
  // A radiance spectrum leaving this object as the sensor receives it: times
  // the view's transmittance, plus the path's own radiance (eq. 9's T_out
  // and L_path; unchanged in vacuum).
  // On the Earth under its atmosphere the path of the point (body frame)
  // with the outward normal there.
  std::vector<double> at_sensor(std::vector<double> spectrum, const Vec3& point_body_m = Vec3::Zero(),
                                const Vec3& normal_body = Vec3::UnitZ()) const;
  void to_sensor(std::vector<double>& spectrum, const Vec3& point_body_m, const Vec3& normal_body) const {
    to_sensor(spectrum, point_body_m, normal_body, true);
  }
  // Eq. 9 term by term at a point of `part` (body frame, outward normal there).
  Eq9Terms eq9_terms(std::int32_t part, const Vec3& point_body_m, const Vec3& normal_body) const;
  // The band radiance of a plain part at the sensor (eq. 9 with L_path).
  double plain_radiance(std::int32_t part) const { return surface->part_radiance(part) + path_radiance_W_cm2_sr_; }
  // One radiance per part, whatever the point (false for the Earth seen
  // through its atmosphere: the path changes with the point).
  bool plain() const { return surface->plain() && !under_atmosphere_; }

  // This object as a source of eq. 7: its area-weighted SRF and emission
  // (per patch where the temperature varies, per part otherwise; the Moon's
  // SRF weighted over the disc it shows the observer, as its albedo map is
  // normalised), made on first use (thread-safe): only frames that light
  // another object or image it as a simple point source read it.
  const LightSpectra& light_spectra() const;

  // Visible fraction of the Sun's disc at a point of this object (umbra 0,
  // penumbra between, sunlight 1) against every other body; aircraft and
  // ground vehicles shade by their parts, 0 or 1 (geometry/part_shadow.hpp;
  // not at a central body's centre, whose eq. 7 disc they hide nothing of).
  double sun_fraction(const Vec3& point_frame_m, const ShadowCasters* near = nullptr) const;

  // The spectral view of this object's light at the sensor: the world's, or
  // with the atmosphere on, the world's seen through the path from the
  // object's centre to the sensor (eq. 9's T_out in every band integral of
  // its surface: images, point sources, picks, target metrics).
  const radiometry::SpectralView& view() const;

 private:
  friend class World;
  friend std::shared_ptr<const World> build_world(const universe::Universe&, const universe::Library&,
                                                  const EngineTime&, const universe::Object&, const ViewDefinition&,
                                                  WorldCache*, const std::set<std::string>*);
  // effective_radiance's reflected light at a located point out of any
  // atmosphere; emits: its emission can reach kNegligible of it.
  // negligible_W_cm2_sr: eq. 7 sources whose light here cannot reach it are
  // left out (negligible_light_W_cm2_sr of the point's emission, or 0);
  // lights_off: lights left out for the whole run (lights_negligible_in).
  double reflected_radiance(const SurfacePoint& point, const ShadowCasters* near, bool& emits,
                            double negligible_W_cm2_sr, const char* lights_off = nullptr) const;
  // The threshold below which other objects' light at a point emitting
  // emitted_W_cm2_sr is left out (0: none left out).
  double negligible_light_W_cm2_sr(const SurfacePoint& point, double emitted_W_cm2_sr) const;
  struct AreaSourcePatch {
    Vec3 direction;              // from the receiver toward the patch, observer frame
    double solid_angle_sr = 0;   // projected solid angle at the receiver
    std::vector<double> radiance;  // toward the receiver, lit by the Sun
  };
  // sum over the patches of t facing the observer of L_k cos A_k (ERRATA eq. 11 times R^2).
  // parts_hide_each_other: the patch is inside another part or another part
  // lies on its line toward the observer (v: toward the observer, body frame).
  bool patch_hidden(const geometry::Patch& patch, const Vec3& v) const;
  // Whether the detailed sum takes each patch's visible share from
  // visible_window (objects of several parts that may hide each other),
  // rather than facing patches (one part; a staged missile: patch_hidden).
  bool hidden_by_window() const { return placed.parts.size() > 1 && !parts_hide_each_other; }
  template <class PatchRadiance>
  double visible_patch_sum(const geometry::Tessellation& t, PatchRadiance radiance) const;
  // to_sensor, with or without L_scatter on the Earth's surface (a band
  // integral adds its band value instead).
  void to_sensor(std::vector<double>& spectrum, const Vec3& point_body_m, const Vec3& normal_body,
                 bool spectral_scatter) const;
  // spectral_radiance into caller buffers (E: the reflected irradiance's scratch).
  // skip_negligible_emission: leave out self-emission below kNegligible of
  // the reflected light (a sample's band value; a spectrum for picks keeps it).
  void spectral_radiance_into(std::int32_t part, const Vec3& point_body_m, const Vec3& normal_body, const Vec3& toward,
                              bool sun_only, std::vector<double>& out, std::vector<double>& E,
                              bool skip_negligible_emission = false) const;
  // Eq. 8 sums of source `light` as seen from this object's centre.
  const std::vector<AreaSourcePatch>& area_source(std::size_t light) const;
  // Adds sum_i E_i (I_i . N) BRDF(I_i, N, O) at a point (eq. 4's bracket).
  void add_reflected_irradiance(const Vec3& point_frame, const Vec3& normal_frame, const Vec3& toward,
                                const radiometry::Brdf& brdf, bool sun_only, std::vector<double>& out,
                                const ShadowCasters* near = nullptr, double negligible_W_cm2_sr = 0.0,
                                const char* lights_off = nullptr) const;
  const World* world_ = nullptr;
  std::unique_ptr<radiometry::SpectralView> seen_through_;  // the atmosphere's T_out, if its path crosses air
  std::vector<double> sun_transmittance_;  // eq. 9's T_in of the Sun's light at the centre; empty: 1
  std::vector<double> path_spectral_;      // eq. 9's L_path + L_scatter from the centre to the sensor; empty: none
  std::vector<double> path_scatter_;       // of which L_scatter
  double path_radiance_W_cm2_sr_ = 0;      // its band integral (eq. 48)
  bool under_atmosphere_ = false;          // the Earth: its points see World::atmosphere.surface's paths
  // Its emission is found before its reflected light (the band's emission
  // can never be left out beside sunlight: the thermal infrared), so that
  // sources negligible beside it are not evaluated.
  bool emission_first_ = false;
  std::int32_t light_ = -1;  // index in World::lights, -1 if not a source
  std::vector<std::vector<geometry::Occulter>> occulters_;  // per light (0 the Sun, 1 + k lights[k]): may shade it
  std::vector<const WorldObject*> part_shadows_;  // vehicles that may shade it from the Sun, by their parts
  std::vector<char> negligible_light_;  // per lights[k]: its light here is below kNegligible of the self-emission
  mutable std::once_flag tessellated_;
  mutable geometry::Tessellation tessellation_;
  mutable std::unique_ptr<std::atomic<double>[]> patch_cache_;  // NaN until computed
  mutable std::once_flag windowed_;
  mutable VisibleWindow window_;
  mutable OnceFlag lit_;  // (read per sample: the lock-free fast path)
  mutable LightSpectra light_spectra_;
  mutable std::mutex area_mutex_;
  mutable std::map<std::size_t, std::vector<AreaSourcePatch>> area_sources_;
};

class World {
 public:
  World() = default;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  EngineTime time;
  std::string sensor_name;
  Observer observer;
  ViewDefinition view;
  SunLight sun;
  std::vector<std::unique_ptr<WorldObject>> objects;  // indexed by id
  std::vector<ObjectLight> lights;                     // every object but the Sun, as eq. 7 sources
  std::vector<std::unique_ptr<SurfaceSpectrum>> spectra;  // the materials in use, through the view
  geometry::RayCaster caster;  // every placed object; ray masks tell how each is imaged
  Sky sky;                     // background light and catalogue stars (a star field in the universe)
  WorldAtmosphere atmosphere;  // the Earth's, when on

  const geometry::SampleGrid& grid() const { return view.grid; }
  const radiometry::SpectralView& spectral() const { return view.spectral; }
  const Fidelity& fidelity() const { return view.fidelity; }
  // Direction of sample (c, r) of the full grid, J2000 axes.
  Vec3 sample_direction(double c, double r) const { return observer.body_to_j2000 * view.grid.direction_body(c, r); }
  // nullptr if the world holds no object of that name (culled by kind, shape
  // none, no state, or the sensor's parent).
  const WorldObject* find(const std::string& name) const;
  // The band radiance of a line of sight (unit direction) that meets no
  // object: the background light (spec 4.1.4), and under the atmosphere
  // the sky's (SkyView: its scatter and emission, the background through
  // it).
  double sky_radiance(const Vec3& d) const;
  // The same per interval, and term by term.
  void sky_spectrum(const Vec3& d, std::vector<double>& out) const;
  Eq9Terms sky_terms(const Vec3& d) const;
};

// Builds the world of `sensor` at t with the library's materials and spectra.
// Throws eoir::Error (no_state for a sensor whose parent has no state,
// unknown_name for an unknown material or spectrum). frame_point_sources:
// given only for the world of a motion sub-step (scene/motion_substeps.hpp),
// the names of the objects the frame time's world images as point sources;
// this world images those as point sources and every other object it would
// image as a point source as small_extended instead.
std::shared_ptr<const World> build_world(const universe::Universe& universe, const universe::Library& library,
                                         const EngineTime& t, const universe::Object& sensor,
                                         const ViewDefinition& view, WorldCache* cache = nullptr,
                                         const std::set<std::string>* frame_point_sources = nullptr);

}  // namespace eoir::scene
