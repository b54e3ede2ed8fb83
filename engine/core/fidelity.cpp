#include "core/fidelity.hpp"

#include "core/error.hpp"

namespace eoir {
namespace {
using F = Fidelity;
using Spec = PropertySpec<F>;

bool power_of_two(std::int64_t n) { return n > 0 && (n & (n - 1)) == 0; }

}  // namespace

const std::vector<std::string>& scene_mode_names() {
  static const std::vector<std::string> names{"coarse", "smooth", "bitmap"};
  return names;
}
const std::vector<std::string>& band_integration_names() {
  static const std::vector<std::string> names{"grid", "exact"};
  return names;
}
const std::vector<std::string>& spectral_quadrature_names() {
  static const std::vector<std::string> names{"midpoint", "left_edge"};
  return names;
}

const std::vector<std::string>& point_tail_names() {
  static const std::vector<std::string> names{"auto", "direct", "multilevel"};
  return names;
}

const std::vector<std::string>& wide_pixel_tables_names() {
  static const std::vector<std::string> names{"quadrant", "product"};
  return names;
}

const std::vector<std::string>& table_fft_sizes_names() {
  static const std::vector<std::string> names{"fitted", "power_of_two"};
  return names;
}

const std::vector<Spec>& fidelity_properties() {
  static const std::vector<Spec> table = [] {
    std::vector<Spec> t;
    t.push_back(number_property<F>("error_budget", "relative",
                                   "Adaptive fidelity: the relative RMS error of the pixel means allowed per frame "
                                   "(e.g. 0.005); the engine chooses the cheapest knobs its error model keeps within "
                                   "it for each frame and reports them (scene/adaptive_fidelity.hpp). 0: off, every "
                                   "knob as set",
                                   [](F& f) -> auto& { return f.error_budget; }, Range{0, 1, false, true}, true));
    t.push_back(enum_property<F, SceneMode>(
        "scene_mode",
        "Scene generation mode (spec 4.2): coarse (one radiance per patch dA), smooth (radiance evaluated at "
        "each sample's own surface point) or bitmap (the same with the material of the body's surface map)",
        [](F& f) -> auto& { return f.scene_mode; }, scene_mode_names(), true));
    t.push_back(integer_property<F>("samples_per_pixel", "count",
                                    "Scene samples per pixel along each axis (spec 4.1.3: 4)",
                                    [](F& f) -> auto& { return f.samples_per_pixel; }, Range{1, 16}, true));
    t.push_back(integer_property<F>("edge_supersampling", "count",
                                    "Sub-samples per axis of each scene sample at a silhouette edge (its hit and a "
                                    "neighbour's differ in object or part): the sample takes their mean, so edge "
                                    "pixels are covered as by samples_per_pixel times this. 1: off",
                                    [](F& f) -> auto& { return f.edge_supersampling; }, Range{1, 16}, true));
    t.push_back(number_property<F>("central_body_patch_size_m", "m",
                                   "Default patch edge of central bodies at the Earth's radius, scaled with the "
                                   "radius (spec 4.2.3: 785 km)",
                                   [](F& f) -> auto& { return f.central_body_patch_size_m; }, Range{0, 1e8, true}, true));
    t.push_back(number_property<F>("object_patch_divisions", "",
                                   "Default patch edge of other objects: their largest part's diameter divided by "
                                   "this (at least 1: a patch no larger than the object)",
                                   [](F& f) -> auto& { return f.object_patch_divisions; }, Range{1, 1e4}, true));
    t.push_back(integer_property<F>("temperature_table_size", "count",
                                    "Entries of the L(T) table of smooth shading where the temperature varies",
                                    [](F& f) -> auto& { return f.temperature_table_size; }, Range{2, 1 << 20}, true));
    t.push_back(number_property<F>("area_source_solid_angle_sr", "sr",
                                   "Illuminating objects looking larger than this from a surface are summed over "
                                   "their tessellation (eq. 8), smaller ones are Lambertian spheres with the phase "
                                   "law (eq. 7); 7.5e-5 sr is the Moon at perigee seen from the Earth (spec 4.1.5.3)",
                                   [](F& f) -> auto& { return f.area_source_solid_angle_sr; }, Range{0, 12.57}, true));
    t.push_back(enum_property<F, BandIntegration>(
        "band_integration",
        "Band integration (eq. 48): grid (the spec 5.3 intervals) or exact (series integral of Planck terms, "
        "independent of the interval count)",
        [](F& f) -> auto& { return f.band_integration; }, band_integration_names(), true));
    t.push_back(enum_property<F, SpectralQuadrature>(
        "spectral_quadrature",
        "Where the grid samples each interval: midpoint (second order) or left_edge (the lambda_i of spec 5.3, "
        "first order)",
        [](F& f) -> auto& { return f.spectral_quadrature; }, spectral_quadrature_names(), true));
    Spec grid = integer_property<F>("psf_grid_size", "count",
                                    "FFT grid size of the system PSF and energy on detector (eq. 40): a power of "
                                    "two, 64-4096",
                                    [](F& f) -> auto& { return f.psf_grid_size; }, Range{64, 4096}, true);
    const auto set_range = grid.set;
    grid.set = [set_range](F& f, const Value& v) {
      const std::int64_t n = integer_of(v, "psf_grid_size");
      if (!power_of_two(n))
        throw Error(Status::out_of_range,
                    "psf_grid_size: must be a power of two in [64, 4096], got " + std::to_string(n));
      set_range(f, v);
    };
    t.push_back(grid);
    t.push_back(integer_property<F>("otf_table_size", "count",
                                    "Entries of the radial OTF table interpolated by the PSF computation",
                                    [](F& f) -> auto& { return f.otf_table_size; }, Range{64, 1 << 24}, true));
    t.push_back(integer_property<F>("psf_alias_margin_steps", "count",
                                    "FFT period of the energy on detector beyond its window, in output steps",
                                    [](F& f) -> auto& { return f.psf_alias_margin_steps; }, Range{1, 1000}, true));
    t.push_back(number_property<F>("psf_fold_budget", "count",
                                   "OTF evaluations allowed when the spectrum is folded onto a coarse grid",
                                   [](F& f) -> auto& { return f.psf_fold_budget; }, Range{1e4, 1e10}, true));
    const struct {
      const char* lambda_f;
      const char* jitter;
      const char* defocus;
      PsfReach F::*reach;
      const char* what;
    } reaches[] = {{"scene_psf_reach_lambda_f", "scene_psf_reach_jitter_sigmas", "scene_psf_reach_defocus_blurs",
                    &F::scene_psf_reach, "guard band of scene samples beyond the field"},
                   {"point_psf_reach_lambda_f", "point_psf_reach_jitter_sigmas", "point_psf_reach_defocus_blurs",
                    &F::point_psf_reach, "window of a point source's energy on detector"},
                   {"point_core_reach_lambda_f", "point_core_reach_jitter_sigmas", "point_core_reach_defocus_blurs",
                    &F::point_core_reach, "core of a point source, from its own tables (the tail beyond)"}};
    for (const auto& r : reaches) {
      PsfReach F::*reach = r.reach;
      t.push_back(number_property<F>(r.lambda_f, "lambda F#",
                                     "PSF reach of the diffraction tail (an Airy pattern keeps 2 / (pi^2 k) of "
                                     "its energy beyond k lambda F#)",
                                     [reach](F& f) -> double& { return (f.*reach).diffraction_lambda_f; },
                                     Range{0, 1e5}, true));
      t.push_back(number_property<F>(r.jitter, "sigma", "PSF reach of the jitter blur, in jitter sigmas",
                                     [reach](F& f) -> double& { return (f.*reach).jitter_sigmas; }, Range{0, 100},
                                     true));
      t.push_back(number_property<F>(r.defocus, "blur diameters",
                                     "PSF reach of the defocus blur, in blur diameters delta / F#",
                                     [reach](F& f) -> double& { return (f.*reach).defocus_blur_diameters; },
                                     Range{0, 100}, true));
    }
    t.push_back(number_property<F>("point_offset_steps_per_lambda_f", "per lambda F#",
                                   "Point sources: sub-pixel offsets per lambda F# (at least 2 per pixel) at which "
                                   "the energy on detector of the core box about a source is tabulated; cubic in the "
                                   "offset between them",
                                   [](F& f) -> auto& { return f.point_offset_steps_per_lambda_f; }, Range{0.5, 64},
                                   true));
    t.push_back(enum_property<F, PointTail>(
        "point_tail",
        "Point sources beyond the core box: direct (pixel by pixel from a table, cost ~ window^2 per source), "
        "multilevel (grids shared by all sources, cost ~ pixels per frame) or auto (direct unless costly and "
        "multilevel over 4 times cheaper for the frame)",
        [](F& f) -> auto& { return f.point_tail; }, point_tail_names(), true));
    t.push_back(number_property<F>("point_table_max_mib", "MiB",
                                   "Point sources: bound on the memory of the model's tables (offsets are "
                                   "coarsened, or the direct tail dropped, to stay within it)",
                                   [](F& f) -> auto& { return f.point_table_max_mib; }, Range{0.25, 65536}, true));
    t.push_back(enum_property<F, WidePixelTables>(
        "point_wide_pixels",
        "Point sources on pixels many lambda F# wide: quadrant (wider than point_quadrant_lambda_f: the "
        "pixel-integrated line-spread functions plus the corner terms of the PSF's quadrant energies, milliseconds "
        "to build, within 1e-4 of the energy per pixel) or product (as before the quadrant tables: 2-D FFT tables up "
        "to 32 lambda F#, seconds to build for wide fields; the plain line-spread product beyond, off by up to "
        "1.4 % of the energy near a pixel corner)",
        [](F& f) -> auto& { return f.point_wide_pixels; }, wide_pixel_tables_names(), true));
    t.push_back(enum_property<F, TableFftSizes>(
        "point_table_fft_sizes",
        "Point sources: FFT sizes of the 2-D tables (pixels up to point_quadrant_lambda_f): fitted (the smallest "
        "even size with factors 2, 3, 5, 7 that holds the table's period, up to 4 times fewer points, its inverse "
        "at the window's rows only and the tail's halo kernels spread by axis: a fresh sensor's tables 2-4 times "
        "faster) or power_of_two (the next power of two, as before; the tables bit for bit as they were, their "
        "totals within the same 1e-3 of the exact path)",
        [](F& f) -> auto& { return f.point_table_fft_sizes; }, table_fft_sizes_names(), true));
    t.push_back(number_property<F>(
        "point_quadrant_lambda_f", "lambda F#",
        "Point sources: pixels wider than this take the quadrant tables (point_wide_pixels quadrant); below 16 "
        "their build costs milliseconds where the 2-D FFT tables take tens (a 64-pixel array at 0.8 lambda F#), "
        "their results differ from those tables' by their errors (about 1e-3 of the energy per pixel), and each "
        "source costs more (the corner terms over its core box, some 40 us at 0.8 lambda F#)",
        [](F& f) -> auto& { return f.point_quadrant_lambda_f; }, Range{0, 32}, true));
    t.push_back(number_property<F>("streak_steps_per_pixel", "per pixel",
                                   "Streaks: sub-steps along the segment a point source covers during the "
                                   "integration, at least this many per pixel",
                                   [](F& f) -> auto& { return f.streak_steps_per_pixel; }, Range{1, 1024}, true));
    t.push_back(number_property<F>("streak_steps_per_lambda_f", "per lambda F#",
                                   "Streaks: sub-steps along the segment, at least this many per lambda F# (the "
                                   "sum over sub-steps of the pixel-integrated PSF, band-limited at 1 / lambda F#, "
                                   "is then its integral)",
                                   [](F& f) -> auto& { return f.streak_steps_per_lambda_f; }, Range{0.1, 64}, true));
    t.push_back(number_property<F>("fft_padding", "guard bands",
                                   "Padding of the scene FFT beyond the guard band, in guard bands (the border "
                                   "samples repeated)",
                                   [](F& f) -> auto& { return f.fft_padding; }, Range{0, 16}, true));
    t.push_back(number_property<F>("scene_memory_max_mib", "MiB",
                                   "Frames whose whole-frame sample and transform buffers would exceed this are made "
                                   "in strips of sample rows, the transform's columns through a temporary file in "
                                   "TMPDIR (memory a few strips; results equal to 1e-9; no scene display, the scene "
                                   "radiance and picks made again on request); 0: always in strips",
                                   [](F& f) -> auto& { return f.scene_memory_max_mib; }, Range{0, 16777216}, true));
    t.push_back(number_property<F>("atmosphere_sub_sample_spacing_cm1", "cm^-1",
                                   "The Earth's atmosphere: transmittance sub-samples of each spectral interval at "
                                   "most this far apart in wavenumber (20: the band models' resolution)",
                                   [](F& f) -> auto& { return f.atmosphere_sub_sample_spacing_cm1; }, Range{1, 1000},
                                   true));
    t.push_back(integer_property<F>("atmosphere_layer_stride", "count",
                                    "The Earth's atmosphere: the profile's levels the paths cross, every n-th (the "
                                    "ground's and the top always kept): layers about n times thicker, densities "
                                    "log-linear across them (1: every level)",
                                    [](F& f) -> auto& { return f.atmosphere_layer_stride; }, Range{1, 16}, true));
    t.push_back(integer_property<F>("atmosphere_surface_nodes", "count",
                                    "The Earth's atmosphere: nodes of T_out, L_path and T_in of the Earth's surface "
                                    "over the zenith cosine, dense toward the horizon (mu = (k / (n - 1))^2)",
                                    [](F& f) -> auto& { return f.atmosphere_surface_nodes; }, Range{3, 1025}, true));
    t.push_back(integer_property<F>("atmosphere_sight_line_nodes", "count",
                                    "The Earth's atmosphere: lines of sight of the sky and the haze that meet the "
                                    "ground; those through the limb and above the horizon take (3 (n - 1) + 2) / 4 + 1",
                                    [](F& f) -> auto& { return f.atmosphere_sight_line_nodes; }, Range{3, 1025},
                                    true));
    t.push_back(integer_property<F>("atmosphere_sky_azimuths", "count",
                                    "The Earth's atmosphere: cells of the sky's single scatter in azimuth from the "
                                    "Sun's vertical plane, 0 to 180 deg (made per frame where a line of sight needs "
                                    "them)",
                                    [](F& f) -> auto& { return f.atmosphere_sky_azimuths; }, Range{3, 1441}, true));
    t.push_back(integer_property<F>("atmosphere_sun_nodes", "count",
                                    "The Earth's atmosphere: nodes of the sunlight's transmittance T_sun over the "
                                    "Sun's zenith cosine at each level of the profile, dense toward the grazing ray",
                                    [](F& f) -> auto& { return f.atmosphere_sun_nodes; }, Range{3, 1025}, true));
    t.push_back(integer_property<F>("atmosphere_downwelling_nodes", "count",
                                    "The Earth's atmosphere: nodes of DownWelling over the Sun's zenith cosine, "
                                    "uniform from 12 deg below the horizon to the zenith",
                                    [](F& f) -> auto& { return f.atmosphere_downwelling_nodes; }, Range{3, 1025},
                                    true));
    t.push_back(integer_property<F>("otf_curve_points", "count", "Samples of the OTF and MTF report curves",
                                    [](F& f) -> auto& { return f.otf_curve_points; }, Range{2, 100000}, true));
    t.push_back(integer_property<F>("target_window_max_half_samples", "count",
                                    "Extended targets (5.13.3): at most (2n + 1)^2 rays average the target and "
                                    "background radiances",
                                    [](F& f) -> auto& { return f.target_window_max_half_samples; }, Range{2, 4096}, true));
    t.push_back(number_property<F>("target_window_extent", "radii",
                                   "Extended targets: half-width of the averaging window in target angular radii",
                                   [](F& f) -> auto& { return f.target_window_extent; }, Range{1, 100}, true));
    return t;
  }();
  return table;
}

void validate(const Fidelity& f) {
  Fidelity copy = f;
  for (const Spec& s : fidelity_properties()) s.set(copy, s.get(f));  // each setter checks its knob
}

}  // namespace eoir
