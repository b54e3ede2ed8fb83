// Images and picks of the last rendered frame (spec 4.1.2, 5.11, 6.2.1).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "capi_internal.hpp"
#include "scene/surface_shader.hpp"
#include "core/constants.hpp"
#include <GeographicLib/Geocentric.hpp>


using namespace eoir;
using eoir::capi::guarded;
using eoir::capi::need;
using eoir::capi::str;

namespace {
struct Extent {
  std::int64_t width, height;
};

Extent extent_of(const scene::Frame& f, int32_t kind) {
  const std::int64_t k = scene::SampleGrid::per_pixel;
  switch (kind) {
    case EOIR_IMAGE_SCENE_RADIANCE:
    case EOIR_IMAGE_SCENE_DISPLAY: return {f.grid.pixels_x * k, f.grid.pixels_y * k};
    case EOIR_IMAGE_SENSOR_ELECTRONS:
    case EOIR_IMAGE_SENSOR_MEAN:
    case EOIR_IMAGE_SENSOR_DISPLAY: return {f.grid.pixels_x, f.grid.pixels_y};
    default: throw Error(Status::out_of_range, "kind: unknown image kind " + std::to_string(kind));
  }
}

void ra_dec_deg(const Eigen::Vector3d& d, double& ra, double& dec) {
  ra = std::atan2(d.y(), d.x()) * constants::deg_per_rad;
  if (ra < 0) ra += 360.0;
  dec = std::asin(std::clamp(d.z() / d.norm(), -1.0, 1.0)) * constants::deg_per_rad;
}
}  // namespace

extern "C" {

EOIR_API eoir_status eoir_render(eoir_engine engine, const char* sensor) {
  return guarded([&] { capi::engine_of(engine).render(str(sensor, "sensor")); });
}

EOIR_API eoir_status eoir_image_info_get(eoir_engine engine, const char* sensor, int32_t kind,
                                         eoir_image_info* info) {
  return guarded([&] {
    const scene::Frame& f = capi::engine_of(engine).frame(str(sensor, "sensor"));
    need(info, "info_out");
    capi::need_size(info->struct_size, sizeof(eoir_image_info), "info_out");
    const Extent e = extent_of(f, kind);
    info->width = static_cast<uint32_t>(e.width);
    info->height = static_cast<uint32_t>(e.height);
    info->kind = kind;
    info->unit = kind == EOIR_IMAGE_SCENE_RADIANCE ? "W/(cm^2 sr)"
                 : (kind == EOIR_IMAGE_SENSOR_ELECTRONS || kind == EOIR_IMAGE_SENSOR_MEAN) ? "electrons"
                                                                                           : "";
    const JulianDate utc = f.time.to(TimeScale::utc);
    info->time_jd_utc[0] = utc.jd1;
    info->time_jd_utc[1] = utc.jd2;
    ra_dec_deg(f.boresight_j2000, info->boresight_ra_deg, info->boresight_dec_deg);
    ra_dec_deg(f.up_j2000, info->up_ra_deg, info->up_dec_deg);
  });
}

EOIR_API eoir_status eoir_image_get(eoir_engine engine, const char* sensor, int32_t kind, double* values,
                                    size_t capacity) {
  return guarded([&] {
    const scene::Frame& f = capi::engine_of(engine).frame(str(sensor, "sensor"));
    need(values, "values");
    const Extent e = extent_of(f, kind);
    const size_t n = static_cast<size_t>(e.width * e.height);
    if (kind == EOIR_IMAGE_SCENE_DISPLAY || kind == EOIR_IMAGE_SENSOR_DISPLAY)
      throw Error(Status::type_mismatch, "kind: display images are bytes; use eoir_image_get_bytes");
    if (capacity < n) throw Error(Status::buffer_too_small, "capacity: " + std::to_string(n) + " values needed");
    if (kind == EOIR_IMAGE_SCENE_RADIANCE) {
      const std::int64_t w = f.grid.width(), g = f.grid.guard_samples();
      for (std::int64_t r = 0; r < e.height; ++r)
        for (std::int64_t c = 0; c < e.width; ++c)
          values[r * e.width + c] = f.scene_radiance[static_cast<size_t>((r + g) * w + c + g)];
    } else {
      const auto& src = kind == EOIR_IMAGE_SENSOR_MEAN ? f.sensor_mean : f.sensor_electrons;
      std::copy(src.begin(), src.end(), values);
    }
  });
}

EOIR_API eoir_status eoir_image_get_bytes(eoir_engine engine, const char* sensor, int32_t kind, uint8_t* bytes,
                                          size_t capacity) {
  return guarded([&] {
    const scene::Frame& f = capi::engine_of(engine).frame(str(sensor, "sensor"));
    need(bytes, "bytes");
    const Extent e = extent_of(f, kind);
    if (kind != EOIR_IMAGE_SCENE_DISPLAY && kind != EOIR_IMAGE_SENSOR_DISPLAY)
      throw Error(Status::type_mismatch, "kind: only display images are bytes; use eoir_image_get");
    const size_t n = static_cast<size_t>(e.width * e.height);
    if (capacity < n) throw Error(Status::buffer_too_small, "capacity: " + std::to_string(n) + " bytes needed");
    const auto& src = kind == EOIR_IMAGE_SCENE_DISPLAY ? f.scene_display : f.sensor_display;
    std::copy(src.begin(), src.end(), bytes);
  });
}

EOIR_API eoir_status eoir_pick_get(eoir_engine engine, const char* sensor, int32_t space, uint32_t x, uint32_t y,
                                   eoir_pick* pick, double* wavelengths_um, double* spectral_radiance,
                                   size_t capacity, size_t* count_out) {
  return guarded([&] {
    const scene::Frame& f = capi::engine_of(engine).frame(str(sensor, "sensor"));
    need(pick, "pick_out");
    capi::need_size(pick->struct_size, sizeof(eoir_pick), "pick_out");
    if (space != 0 && space != 1) throw Error(Status::out_of_range, "space: 0 (sample) or 1 (pixel)");
    const std::int64_t k = scene::SampleGrid::per_pixel;
    const std::int64_t limit_x = space == 0 ? f.grid.pixels_x * k : f.grid.pixels_x;
    const std::int64_t limit_y = space == 0 ? f.grid.pixels_y * k : f.grid.pixels_y;
    if (x >= limit_x) throw Error(Status::out_of_range, "x: " + std::to_string(x) + " >= " + std::to_string(limit_x));
    if (y >= limit_y) throw Error(Status::out_of_range, "y: " + std::to_string(y) + " >= " + std::to_string(limit_y));
    // A pixel is picked at its centre sample (the third of its four, 0-based 2).
    const std::int64_t c = (space == 0 ? x : x * k + k / 2) + f.grid.guard_samples();
    const std::int64_t r = (space == 0 ? y : y * k + k / 2) + f.grid.guard_samples();
    const size_t i = static_cast<size_t>(r * f.grid.width() + c);
    // Cast this one sample's ray again, with range, point and patch.
    const Eigen::Vector3d d = f.body_to_j2000 * f.grid.direction_body(c, r);
    std::vector<geometry::Hit> hits;
    geometry::Hit hit;
    if (f.samples[i].object_id >= 0) {
      geometry::RayCaster caster;
      caster.build(f.placed);
      caster.cast({d}, hits, 1);
      hit = hits[0];
    }
    const uint32_t size = pick->struct_size;
    std::memset(pick, 0, sizeof(eoir_pick));
    pick->struct_size = size;
    pick->effective_radiance = f.scene_radiance[i];
    ra_dec_deg(d, pick->right_ascension_deg, pick->declination_deg);
    std::vector<double> spectrum(f.spectral.sample_wavelengths_um.size(), 0.0);
    if (hit.object_id < 0) {
      pick->hit = 0;
      pick->patch = -1;
      pick->range_m = geometry::sky_range_m;
    } else {
      const scene::FrameObject& o = f.objects[static_cast<size_t>(hit.object_id)];
      pick->hit = 1;
      std::snprintf(pick->object, sizeof pick->object, "%s", o.name.c_str());
      pick->patch = hit.patch;
      pick->range_m = hit.range_m;
      const geometry::PlacedObject* po = nullptr;
      for (const auto& candidate : f.placed)
        if (candidate.object_id == hit.object_id) po = &candidate;
      if (!po) throw Error(Status::internal, "pick: sample hit an object that was not cast against");
      const scene::SurfaceShader shader(o, *po, f.spectral, f.smooth);
      pick->temperature_K = shader.temperature_at(hit.part, hit.point_body_m);
      if (o.central_body) {
        // Geodetic latitude/longitude on the body's ellipsoid (GeographicLib):
        // WGS84 on the Earth-fixed Earth; other bodies' axes are J2000-aligned.
        const double a = o.equatorial_radius_m, flattening = (a - o.polar_radius_m) / a;
        double lat = 0, lon = 0, h = 0;
        GeographicLib::Geocentric(a, flattening)
            .Reverse(hit.point_body_m.x(), hit.point_body_m.y(), hit.point_body_m.z(), lat, lon, h);
        pick->has_geodetic = 1;
        pick->latitude_deg = lat;
        pick->longitude_deg = lon;
      }
      spectrum = scene::spectral_radiance(scene::SurfacePoint{pick->temperature_K, o.part(hit.part).reflectance},
                                          f.spectral);
    }
    if (count_out) *count_out = spectrum.size();
    if (wavelengths_um && spectral_radiance) {
      if (capacity < spectrum.size())
        throw Error(Status::buffer_too_small, "capacity: " + std::to_string(spectrum.size()) + " values needed");
      std::copy(f.spectral.sample_wavelengths_um.begin(), f.spectral.sample_wavelengths_um.end(), wavelengths_um);
      std::copy(spectrum.begin(), spectrum.end(), spectral_radiance);
    }
  });
}
}
