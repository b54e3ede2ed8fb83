// Every knob that trades speed for accuracy, in one documented struct (after
// GalSim's GSParams): its default and meaning here, its name, range and unit
// in fidelity_properties(). Each sensor carries one (its scene generator and
// sensor model use it); it is settable as sensor properties, saved in .scd
// and sensor files, and echoed into every output.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/value.hpp"

namespace eoir {

// Scene generation mode (spec 4.2): coarse gives each sample the radiance of
// the centre of its patch dA (4.2.1); smooth evaluates each sample's own
// surface point (4.2.2); bitmap does the same with the material (and, on the
// Earth, land or water) that the body's surface map holds there (4.2.3).
enum class SceneMode : int { coarse = 0, smooth = 1, bitmap = 2 };
// Band integration of eq. 48: on the spectral grid of spec 5.3, or exactly
// (series integral of Planck terms, independent of the interval count).
enum class BandIntegration : int { grid = 0, exact = 1 };
// Where the grid samples each of its N intervals (radiometry/band_integral.hpp):
// the midpoint (second order) or the left edge lambda_i of spec 5.3 (first order).
enum class SpectralQuadrature : int { interval_midpoint = 0, interval_left_edge = 1 };
// How a point source's energy beyond its core box reaches the pixels
// (sensor/point_source_model.hpp): pixel by pixel from a table (direct, cost
// ~ window^2 per source), through grids of spacing a, 2a, 4a ... pixels
// shared by all sources (multilevel, cost ~ pixels per frame), or for each
// frame direct unless it is costly and multilevel costs over 4 times less
// (automatic). Both keep each source's energy, centroid and second moments.
enum class PointTail : int { automatic = 0, direct = 1, multilevel = 2 };

// Point-source tables of pixels many lambda F# wide
// (sensor/point_source_model.hpp): quadrant (from point_quadrant_lambda_f
// on: the line-spread product plus the corner terms of the PSF's quadrant
// energies) or product (the plain line-spread product from 32 lambda F# on,
// 2-D FFT tables below, as the engine had them before the quadrant tables).
enum class WidePixelTables : int { quadrant = 0, product = 1 };
// FFT sizes of the 2-D point-source tables: fitted (the smallest even size
// with factors 2, 3, 5, 7 that holds the table's period) or power_of_two (the
// next power of two, as before: the tables bit for bit as they were).
enum class TableFftSizes : int { fitted = 0, power_of_two = 1 };

// How far the PSF reaches in the focal plane: k_d lambda F# of diffraction
// tail, k_j sigma of jitter (times the focal length) and k_f defocus blur
// diameters delta / F#. An Airy pattern holds about 2 / (pi^2 k_d) of its
// energy beyond k_d lambda F#.
struct PsfReach {
  double diffraction_lambda_f = 20.0;
  double jitter_sigmas = 4.0;
  double defocus_blur_diameters = 1.0;
};

struct Fidelity {
  // Adaptive fidelity (scene/adaptive_fidelity.hpp): the relative RMS error
  // of the pixel means allowed per frame; the engine then chooses the
  // cheapest knobs that its error model keeps within it. 0: off, every knob
  // as set.
  double error_budget = 0.0;
  // Scene generator (spec 4.1-4.2).
  SceneMode scene_mode = SceneMode::coarse;
  std::int64_t samples_per_pixel = 4;  // scene samples per pixel and axis (spec 4.1.3: 4)
  // Sub-samples per axis of each scene sample at a silhouette edge (its hit
  // and a 4-neighbour's differ in object or part): the sample takes their
  // mean, so edge pixels are covered as by samples_per_pixel times this. 1: off.
  std::int64_t edge_supersampling = 1;
  // Default patch edge where an object's patch_size_m is 0 (spec 4.1.5.2):
  // central bodies scaled from the Earth's 785 km (spec 4.2.3), other objects
  // their largest part's diameter divided by this.
  double central_body_patch_size_m = 785.0e3;  // at the Earth's equatorial radius
  double object_patch_divisions = 8.0;
  std::int64_t temperature_table_size = 4096;  // L(T) table of smooth shading of varying surfaces
  // Illumination (spec 4.1.5.3): sources looking larger than this from a
  // surface are summed over their tessellation (eq. 8), smaller ones are
  // Lambertian spheres (eq. 7): the Moon at perigee seen from the Earth.
  double area_source_solid_angle_sr = 7.5e-5;
  // Spectral (spec 5.3, eq. 48).
  BandIntegration band_integration = BandIntegration::grid;
  SpectralQuadrature spectral_quadrature = SpectralQuadrature::interval_midpoint;
  // Sensor model (spec 5.6-5.11).
  std::int64_t psf_grid_size = 512;      // FFT grid of the PSF and energy on detector (eq. 40), power of two
  std::int64_t otf_table_size = 16384;   // radial OTF table the PSF fold interpolates (error < 1e-6)
  std::int64_t psf_alias_margin_steps = 9;     // FFT period beyond the window, in output steps
  double psf_fold_budget = 4194304.0;          // OTF evaluations allowed when the spectrum is folded
  PsfReach scene_psf_reach{20.0, 4.0, 1.0};    // guard band of scene samples beyond the field (~1 % tail)
  PsfReach point_psf_reach{500.0, 6.0, 1.0};   // window of a point source's energy on detector (~4e-4 tail)
  // Point-source model (sensor/point_source_model.hpp): tables of the energy
  // on detector against the sub-pixel offset, built once per sensor.
  PsfReach point_core_reach{8.0, 4.0, 1.0};     // a: each source's own table out to a..2a pixels, the tail beyond
  double point_offset_steps_per_lambda_f = 4.0;  // sub-pixel offsets per lambda F# of that table (cubic in the offset)
  PointTail point_tail = PointTail::automatic;   // how the energy beyond the core box is added
  double point_table_max_mib = 64.0;             // bound on the model's tables (MiB)
  WidePixelTables point_wide_pixels = WidePixelTables::quadrant;  // tables of wide pixels
  TableFftSizes point_table_fft_sizes = TableFftSizes::fitted;  // FFT sizes of the 2-D tables
  double point_quadrant_lambda_f = 16.0;  // quadrant tables from this pixel width (lambda F#) on; 0: every pixel
  // Streaks (a source moving during the integration): sub-steps along the
  // segment, at least this many per pixel and per lambda F#.
  double streak_steps_per_pixel = 8.0;
  double streak_steps_per_lambda_f = 1.0;
  double fft_padding = 1.0;  // FFT padding beyond the guard band, in guard bands
  // Frames whose whole-frame sample and transform buffers
  // (sensor::whole_frame_bytes) exceed this are made in strips of rows
  // (sensor/scene_convolution.hpp): 0 always, the whole frame never kept.
  double scene_memory_max_mib = 1024.0;
  // The Earth's atmosphere (spec 4.3.1.1, eq. 9; issue 20 item 8): its
  // tables, made once per atmosphere and band (the sky's cells per frame).
  // Transmittance sub-samples of each spectral interval at most this far
  // apart in wavenumber (atmosphere/path_optics.hpp: the band models' 20 cm^-1).
  double atmosphere_sub_sample_spacing_cm1 = 20.0;
  // The profile's levels the paths cross: every n-th (the ground's and the
  // top always), so its layers are about n times thicker (1: every level).
  std::int64_t atmosphere_layer_stride = 1;
  std::int64_t atmosphere_surface_nodes = 33;  // T_out, L_path, T_in of the Earth's surface over the zenith cosine
  // Lines of sight of the sky and the haze (scene/sight_lines.hpp) that meet
  // the ground; those through the limb and (from inside) above the horizon
  // take (3 (n - 1) + 2) / 4 + 1 (25 of 33).
  std::int64_t atmosphere_sight_line_nodes = 33;
  std::int64_t atmosphere_sky_azimuths = 49;      // sky cells from the Sun's vertical plane, 0..pi
  std::int64_t atmosphere_sun_nodes = 33;         // T_sun over the Sun's zenith cosine (atmosphere/single_scatter.hpp)
  std::int64_t atmosphere_downwelling_nodes = 40; // DownWelling over the Sun's zenith cosine (scene/downwelling.hpp)
  // Reports (spec 5.12-5.13).
  std::int64_t otf_curve_points = 101;            // samples of the OTF/MTF report curves
  std::int64_t target_window_max_half_samples = 64;  // extended-target window: at most (2n+1)^2 rays
  double target_window_extent = 1.5;              // window half-width in target angular radii
};

// The knobs as named, typed properties of a Fidelity (README "Fidelity").
const std::vector<PropertySpec<Fidelity>>& fidelity_properties();
const std::vector<std::string>& scene_mode_names();
const std::vector<std::string>& band_integration_names();
const std::vector<std::string>& spectral_quadrature_names();
const std::vector<std::string>& point_tail_names();
const std::vector<std::string>& wide_pixel_tables_names();

// Throws out_of_range naming the field unless every knob is in its range
// (and psf_grid_size a power of two).
void validate(const Fidelity& f);

}  // namespace eoir
