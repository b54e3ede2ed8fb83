// What one object's surface is made of and how hot it is (spec 4.1.4.1,
// 4.3.1.3): per shape part its material as the view sees it and its
// temperature, the thermal field that varies it, a tabulated self-radiance
// (spec 4.1.4) in place of eps B(T), and on central bodies the geography
// that maps, in bitmap mode, give each point its own material (spec 4.2.3),
// scaled by the land's brightness within its class, and, with the
// climatology thermal model, land or water temperatures; on the Earth the
// optional cloud layer blends a cloud top over the surface by its fraction
// (issue 20 item 7). The world combines it with the light that reaches a
// point (eq. 4) through reflect().
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/time.hpp"
#include "radiometry/spectral_view.hpp"
#include "scene/surface_spectrum.hpp"
#include "scene/thermal_field.hpp"
#include "scene/thermal_models.hpp"
#include "universe/surface_climatology.hpp"
#include "universe/surface_map.hpp"

namespace eoir::scene {

using Vec3 = Eigen::Vector3d;

struct PartSurface {
  const SurfaceSpectrum* spectrum = nullptr;  // the world's, shared by parts of the same material
  double temperature_K = 0.0;                 // the uniform thermal model's (or the eclipse model's result)
  std::vector<double> self_radiance;          // this part's tabulated radiance (a plume's, spec 4.3.6), or empty
  bool emits_only = false;                    // reflects nothing whatever its material (a plume: spec 4.3.6)
};

// A point of the surface: its part, position and outward normal (body frame).
struct SurfaceSite {
  std::int32_t part = 0;
  Vec3 point_body_m = Vec3::Zero();
  Vec3 normal_body = Vec3::UnitZ();
};

// What the surface is at a site (SurfaceModel::at): its material from the
// maps, and where it is for its temperature (SurfaceModel::temperature_K),
// which only self-emission needs.
struct SurfacePoint {
  SurfaceSite site;
  const SurfaceSpectrum* spectrum = nullptr;
  double latitude_deg = 0.0, longitude_deg = 0.0;  // central bodies with maps or a climatology
  double sin_latitude = 0.0, cos_latitude = 1.0;
  double reflectance_scale = 1.0;  // multiplies the spectrum's SRF (bitmap mode: the land's brightness)
  double cloud_fraction = 0.0;     // the cloud layer's share of the point
  bool on_land = false;            // the land mask's cell, set by read_maps (a climatology's land or water table)
};

// A central body's coordinates and the maps read at a point.
struct Geography {
  double equatorial_radius_m = 0, polar_radius_m = 0;
  bool geodetic = false;  // the Earth: WGS84 geodetic latitude; others planetocentric
  // Bitmap mode: the material of each land-cover class (index 1..18), or of
  // each albedo value (index 0..255).
  const universe::RasterLevel* land_cover = nullptr;
  std::vector<const SurfaceSpectrum*> class_spectra;
  // Bitmap mode: the land's brightness relative to its class's mean, which
  // scales the class's SRF (at most to SRF 1; not water's).
  const universe::RasterLevel* land_brightness = nullptr;
  // The cloud layer: its fraction, the cloud top's material, height and temperature.
  const universe::RasterLevel* clouds = nullptr;
  const SurfaceSpectrum* cloud_spectrum = nullptr;
  double cloud_height_m = 0, cloud_temperature_K = 0;
  const universe::RasterLevel* albedo = nullptr;
  std::vector<const SurfaceSpectrum*> albedo_spectra;
  // Thermal model climatology: land or water from the mask, then the tables.
  const universe::RasterLevel* land_mask = nullptr;
  const universe::SurfaceClimatology* climatology = nullptr;
  ClimatologyInstant climatology_now;  // the tables and the Sun at the frame's time
  // The latitude (geodetic on the Earth), its sine and cosine, and the
  // longitude of each point's site (site.point_body_m).
  void locate(SurfacePoint* const* points, std::size_t n) const;
  bool bitmap() const { return land_cover || albedo; }
};

class SurfaceModel {
 public:
  // self_radiance: the tabulated spectral radiance at the view's wavelengths
  // (interval means), or empty. temperature_table_size > 0 builds the L(T)
  // table of interpolated emission (smooth mode) where the temperature varies
  // over a part. `geography` may be empty.
  SurfaceModel(std::vector<PartSurface> parts, ThermalField thermal, std::vector<double> self_radiance,
               Geography geography, const radiometry::SpectralView& view, std::int64_t temperature_table_size);
  const PartSurface& part(std::int32_t i) const { return parts_[index(i)]; }
  std::size_t part_count() const { return parts_.size(); }
  // The material at a site (the map's in bitmap mode).
  SurfacePoint at(const SurfaceSite& site) const;
  // The same in two steps, so that the map cells of many points can be
  // asked of the memory together: the point's coordinates (located), the
  // cells it reads asked for (prefetch_maps), then read (read_maps).
  SurfacePoint located(const SurfaceSite& site) const;
  // Whether located reads the point's coordinates (maps, clouds or a
  // climatology), and the same for many points at once (points made by
  // unlocated: their site and spectrum).
  bool locates() const {
    const Geography& g = geography_;
    return g.bitmap() || g.clouds || (g.climatology && g.land_mask);
  }
  SurfacePoint unlocated(const SurfaceSite& site) const {
    return SurfacePoint{site, parts_[index(site.part)].spectrum};
  }
  void locate(SurfacePoint* const* points, std::size_t n) const {
    if (locates()) geography_.locate(points, n);
  }
  void prefetch_maps(const SurfacePoint& point) const;
  void read_maps(SurfacePoint& point) const;
  // The temperature there (the thermal model or the climatology).
  double temperature_K(const SurfacePoint& point) const { return temperature_term(point).value_K(); }
  TemperatureTerm temperature_term(const SurfacePoint& point) const;
  // Some part (or map class) reflects light in the band.
  bool reflects() const { return reflects_; }
  bool reflects(const SurfacePoint& point) const {
    const PartSurface& part = parts_[index(point.site.part)];
    return self_radiance_.empty() && part.self_radiance.empty() && !part.emits_only &&
           (point.spectrum->reflects() || point.cloud_fraction > 0);
  }
  // The reflected spectrum at a point (eq. 4, SRF x E): `out` = the sum over
  // its layers (the surface, and the cloud top by its fraction) of the
  // layer's SRF times irradiance(brdf, height_m, E), which fills E with the
  // light the layer's BRDF reflects toward the observer at the point raised
  // by height_m along its normal. E is scratch. Only where reflects(point).
  template <class Irradiance>
  void reflect(const SurfacePoint& point, Irradiance&& irradiance, std::vector<double>& out,
               std::vector<double>& E) const;
  // The greatest height above the surface at which reflect raises a point
  // (the cloud top's; 0 without clouds).
  double layer_height_m() const { return geography_.clouds ? geography_.cloud_height_m : 0.0; }
  // At least the point's SRF (its layers blended) at any wavelength.
  double srf_bound(const SurfacePoint& point) const {
    const double f = point.cloud_fraction;
    double most = 0.0;
    if (f < 1.0 && point.spectrum->reflects()) most = (1.0 - f) * point.reflectance_scale * point.spectrum->max_srf();
    if (f > 0.0) most += f * geography_.cloud_spectrum->max_srf();
    return most;
  }
  // Adds weight x the point's SRF (its layers blended) to `srf`.
  void add_srf(const SurfacePoint& point, double weight, std::vector<double>& srf) const;
  // The temperature or the material varies over a part.
  bool varying() const {
    return thermal_.subsolar || geography_.bitmap() || geography_.climatology || geography_.clouds;
  }
  // One radiance per part, whatever the point and the light.
  bool plain() const { return !reflects_ && !varying(); }
  bool bitmap() const { return geography_.bitmap(); }
  // Its radiance is tabulated (no temperature, no material's emissivity).
  bool tabulated() const { return !self_radiance_.empty(); }

  // Self-emission eps B(T) (or the tabulated radiance) at the view's
  // wavelengths added to `out`, and its band integral (eq. 48; exact where
  // the view says).
  void add_emission(const SurfacePoint& point, std::vector<double>& out) const;
  double emission_radiance(const SurfacePoint& point) const;
  // The same, or through the L(T) table (interpolated), at many points,
  // their temperatures taken together (temperature_terms_K).
  void emission_radiances(const SurfacePoint* const* points, std::size_t n, bool interpolated, double* out) const;
  // At least emission_radiance(s), interpolated or not, anywhere
  // on the surface (infinity for a tabulated radiance).
  double emission_bound() const { return emission_bound_; }
  // At most emission_radiance anywhere on the surface: its materials at the
  // coldest temperature it can have (0 where the thermal field reaches 0 K,
  // and for a tabulated radiance, which reflects nothing).
  double emission_floor() const { return emission_floor_; }
  // At least SRF(lambda) x BRDF x cos(incidence) (1/sr) of any of its
  // materials at any wavelength and geometry, and at least SRF(lambda) (0
  // if none reflects).
  double reflection_bound_per_sr() const { return reflection_bound_per_sr_; }
  // The largest N.L value of any of its BRDFs (1/sr; Brdf::max_projected_value_per_sr).
  double brdf_bound_per_sr() const { return brdf_bound_per_sr_; }
  double srf_bound() const { return srf_bound_; }
  // plain(): the effective radiance of a whole part.
  double part_radiance(std::int32_t part) const { return part_radiance_[index(part)]; }
  const Geography& geography() const { return geography_; }

 private:
  // emission_radiance(_interpolated) with the point's temperature from
  // temperature() (called only where it is needed).
  template <class TemperatureK>
  double emission_radiance(const SurfacePoint& point, TemperatureK temperature) const;
  template <class TemperatureK>
  double emission_radiance_interpolated(const SurfacePoint& point, TemperatureK temperature) const;
  static std::size_t index(std::int32_t part) { return static_cast<std::size_t>(part < 0 ? 0 : part); }
  std::vector<PartSurface> parts_;
  ThermalField thermal_;
  std::vector<double> self_radiance_;
  Geography geography_;
  bool mask_on_cover_cells_ = false;  // the land mask's level has the land cover's cells
  const radiometry::SpectralView* view_;
  bool reflects_ = false;
  std::vector<double> part_radiance_;
  double table_T0_ = 0, table_dT_ = 0;
  double emission_bound_ = 0, emission_floor_ = 0, reflection_bound_per_sr_ = 0, srf_bound_ = 0;
  double brdf_bound_per_sr_ = 0;
  double cloud_emission_ = 0;  // the cloud top's band radiance at its (one) temperature
  std::vector<std::vector<double>> table_;  // per part, L at T0 + k dT
};

template <class Irradiance>
void SurfaceModel::reflect(const SurfacePoint& point, Irradiance&& irradiance, std::vector<double>& out,
                           std::vector<double>& E) const {
  const std::size_t n = out.size();
  const double f = point.cloud_fraction;
  std::fill(out.begin(), out.end(), 0.0);
  if (f < 1.0 && point.spectrum->reflects()) {
    E.assign(n, 0.0);
    irradiance(point.spectrum->brdf(), 0.0, E);
    const std::vector<double>& srf = point.spectrum->srf();
    const double w = (1.0 - f) * point.reflectance_scale;
    for (std::size_t i = 0; i < n; ++i) out[i] = E[i] * (w * srf[i]);
  }
  if (f > 0.0) {
    const SurfaceSpectrum& cloud = *geography_.cloud_spectrum;
    E.assign(n, 0.0);
    irradiance(cloud.brdf(), geography_.cloud_height_m, E);
    for (std::size_t i = 0; i < n; ++i) out[i] += E[i] * (f * cloud.srf()[i]);
  }
}

}  // namespace eoir::scene
