// Images and picks of the last rendered frame (spec 4.1.2, 5.11, 6.2.1).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>

#include "capi_internal.hpp"
#include "sensor/detector.hpp"

using namespace eoir;
using eoir::capi::need;
using eoir::capi::str;
using eoir::capi::with_engine;

namespace {
struct Extent {
  std::int64_t width, height;
};

Extent extent_of(const Frame& f, int32_t kind) {
  const geometry::SampleGrid& g = f.grid();
  switch (kind) {
    case EOIR_IMAGE_SCENE_RADIANCE:
    case EOIR_IMAGE_SCENE_DISPLAY: return {g.field_width(), g.field_height()};
    case EOIR_IMAGE_SENSOR_ELECTRONS:
    case EOIR_IMAGE_SENSOR_MEAN:
    case EOIR_IMAGE_SENSOR_DISPLAY:
    case EOIR_IMAGE_SENSOR_ADU: return {g.pixels_x, g.pixels_y};
    default: throw Error(Status::out_of_range, "kind: unknown image kind " + std::to_string(kind));
  }
}
// A frame made in strips keeps no scene display.
void need_scene_display(const Frame& f) {
  if (f.scene_in_strips)
    throw Error(Status::no_state,
                "kind: the frame was made in strips (its buffers exceed the sensor's scene_memory_max_mib): no scene "
                "display");
}
// The frame's ADU image; no_state unless it was rendered with the detector stage.
const std::vector<std::uint32_t>& adu_of(const Frame& f) {
  if (f.sensor.adu.empty())
    throw Error(Status::no_state, "kind: the frame was rendered with detector_model off: no ADU image");
  return f.sensor.adu;
}
}  // namespace

extern "C" {

EOIR_API eoir_status eoir_render(eoir_engine engine, const char* sensor) {
  return with_engine(engine, [&](Engine& e) { e.render(str(sensor, "sensor")); });
}

EOIR_API eoir_status eoir_image_info_get(eoir_engine engine, const char* sensor, int32_t kind,
                                         eoir_image_info* info) {
  return with_engine(engine, [&](Engine& e) {
    const Frame& f = e.frame(str(sensor, "sensor"));
    need(info, "info_out");
    constexpr size_t v11_size = offsetof(eoir_image_info, start_jd_utc);  // the struct before 1.6 appended
    capi::need_size(info->struct_size, v11_size, "info_out");
    const Extent ext = extent_of(f, kind);
    if (kind == EOIR_IMAGE_SENSOR_ADU) adu_of(f);
    if (kind == EOIR_IMAGE_SCENE_DISPLAY) need_scene_display(f);
    const uint32_t size = info->struct_size;
    eoir_image_info full{};
    full.struct_size = size;
    full.width = static_cast<uint32_t>(ext.width);
    full.height = static_cast<uint32_t>(ext.height);
    full.kind = kind;
    full.unit = kind == EOIR_IMAGE_SCENE_RADIANCE ? "W/(cm^2 sr)"
                : (kind == EOIR_IMAGE_SENSOR_ELECTRONS || kind == EOIR_IMAGE_SENSOR_MEAN) ? "electrons"
                : kind == EOIR_IMAGE_SENSOR_ADU                                           ? "adu"
                                                                                          : "";
    const auto utc = [](const EngineTime& t, double (&out)[2]) {
      const JulianDate d = t.to(TimeScale::utc);
      out[0] = d.jd1;
      out[1] = d.jd2;
    };
    utc(f.time(), full.time_jd_utc);
    const scene::World& w = *f.world;
    const Eigen::Matrix3d& body_to_j2000 = w.observer.body_to_j2000;
    scene::ra_dec_deg(body_to_j2000.col(2), full.boresight_ra_deg, full.boresight_dec_deg);
    scene::ra_dec_deg(body_to_j2000.col(1), full.up_ra_deg, full.up_dec_deg);
    const double half_s = 0.5 * w.view.integration_time_s;
    utc(f.time().plus_seconds(-half_s), full.start_jd_utc);
    utc(f.time().plus_seconds(half_s), full.end_jd_utc);
    // The WCS per sensor pixel, per sample for the scene kinds.
    const scene::AstrometricWcs& wcs = f.astrometric_wcs;
    const bool scene_kind = kind == EOIR_IMAGE_SCENE_RADIANCE || kind == EOIR_IMAGE_SCENE_DISPLAY;
    const double per_unit = scene_kind ? 1.0 / static_cast<double>(f.grid().per_pixel) : 1.0;
    full.astrometric_ra_deg = wcs.ra_deg;
    full.astrometric_dec_deg = wcs.dec_deg;
    for (int k = 0; k < 4; ++k) full.astrometric_cd_deg[k] = wcs.cd_deg[k] * per_unit;
    for (int k = 0; k < 3; ++k) {
      full.observer_position_m[k] = w.observer.position_m[k];
      full.observer_velocity_m_s[k] = w.observer.velocity_m_s[k];
      full.observer_earth_fixed_m[k] = f.observer_earth_fixed_m[k];
    }
    const sensor::SensorModel& model = *f.sensor_model;
    const double saturation = model.metrics.saturation_electrons;
    full.saturation_electrons = std::isfinite(saturation) ? saturation : 0.0;
    full.read_noise_electrons = model.parameters.noise_enabled ? model.metrics.dark_noise_electrons : 0.0;
    const universe::DetectorParameters& d = model.parameters.detector;
    if (d.enabled) {
      // The detector stage (sensor/detector.hpp) in place of eqs. 53-55.
      full.saturation_electrons = d.full_well_e;
      full.read_noise_electrons = model.parameters.noise_enabled ? d.read_noise_e : 0.0;
      full.gain_e_per_adu = d.gain_e_per_adu;
      full.bias_adu = d.bias_adu;
      full.saturation_adu = sensor::saturation_adu(d);
      full.adc_max_adu = sensor::adc_max_adu(d);
    }
    std::memcpy(info, &full, std::min<size_t>(size, sizeof full));  // what the caller's version holds
  });
}

EOIR_API eoir_status eoir_frame_fidelity_get(eoir_engine engine, const char* sensor, char* buffer, size_t capacity,
                                             size_t* length_out) {
  return with_engine(engine, [&](Engine& e) {
    const Frame& f = e.frame(str(sensor, "sensor"));
    need(length_out, "length_out");
    const std::string text = f.fidelity.json();
    *length_out = text.size();
    if (!buffer) return;
    if (text.size() + 1 > capacity)
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(text.size() + 1) + " bytes needed");
    std::memcpy(buffer, text.c_str(), text.size() + 1);
  });
}

EOIR_API eoir_status eoir_image_get(eoir_engine engine, const char* sensor, int32_t kind, double* values,
                                    size_t capacity) {
  return with_engine(engine, [&](Engine& e) {
    const Frame& f = e.frame(str(sensor, "sensor"));
    need(values, "values");
    const Extent ext = extent_of(f, kind);
    const size_t n = static_cast<size_t>(ext.width * ext.height);
    if (kind == EOIR_IMAGE_SCENE_DISPLAY || kind == EOIR_IMAGE_SENSOR_DISPLAY)
      throw Error(Status::type_mismatch, "kind: display images are bytes; use eoir_image_get_bytes");
    if (capacity < n) throw Error(Status::buffer_too_small, "capacity: " + std::to_string(n) + " values needed");
    if (kind == EOIR_IMAGE_SCENE_RADIANCE) {
      e.scene_field_radiance(str(sensor, "sensor"), values);
    } else if (kind == EOIR_IMAGE_SENSOR_ADU) {
      const auto& adu = adu_of(f);
      std::copy(adu.begin(), adu.end(), values);
    } else {
      const auto& src = kind == EOIR_IMAGE_SENSOR_MEAN ? f.sensor.mean_electrons : f.sensor.electrons;
      std::copy(src.begin(), src.end(), values);
    }
  });
}

EOIR_API eoir_status eoir_image_get_bytes(eoir_engine engine, const char* sensor, int32_t kind, uint8_t* bytes,
                                          size_t capacity) {
  return with_engine(engine, [&](Engine& e) {
    const Frame& f = e.frame(str(sensor, "sensor"));
    need(bytes, "bytes");
    const Extent ext = extent_of(f, kind);
    if (kind != EOIR_IMAGE_SCENE_DISPLAY && kind != EOIR_IMAGE_SENSOR_DISPLAY)
      throw Error(Status::type_mismatch, "kind: only display images are bytes; use eoir_image_get");
    const size_t n = static_cast<size_t>(ext.width * ext.height);
    if (kind == EOIR_IMAGE_SCENE_DISPLAY) need_scene_display(f);
    if (capacity < n) throw Error(Status::buffer_too_small, "capacity: " + std::to_string(n) + " bytes needed");
    const auto& src = kind == EOIR_IMAGE_SCENE_DISPLAY ? f.scene_display() : f.sensor_display();
    std::copy(src.begin(), src.end(), bytes);
  });
}

EOIR_API eoir_status eoir_image_get_adu(eoir_engine engine, const char* sensor, uint32_t* adu, size_t capacity) {
  return with_engine(engine, [&](Engine& e) {
    const Frame& f = e.frame(str(sensor, "sensor"));
    need(adu, "adu");
    const std::vector<std::uint32_t>& src = adu_of(f);
    if (capacity < src.size())
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(src.size()) + " values needed");
    std::copy(src.begin(), src.end(), adu);
  });
}

EOIR_API eoir_status eoir_pick_get(eoir_engine engine, const char* sensor, int32_t space, uint32_t x, uint32_t y,
                                   eoir_pick* pick, double* wavelengths_um, double* spectral_radiance,
                                   size_t capacity, size_t* count_out) {
  return with_engine(engine, [&](Engine& e) {
    const std::string name = str(sensor, "sensor");
    need(pick, "pick_out");
    capi::need_size(pick->struct_size, sizeof(eoir_pick), "pick_out");
    const scene::Pick p = e.pick(name, space, x, y);
    const size_t n = p.wavelengths_um.size();
    if (wavelengths_um && spectral_radiance && capacity < n)
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(n) + " values needed");
    const uint32_t size = pick->struct_size;
    std::memset(pick, 0, sizeof(eoir_pick));
    pick->struct_size = size;
    pick->hit = p.hit ? 1 : 0;
    capi::copy_text(pick->object, p.object);
    pick->patch = p.patch;
    pick->range_m = p.range_m;
    pick->has_geodetic = p.has_geodetic ? 1 : 0;
    pick->latitude_deg = p.latitude_deg;
    pick->longitude_deg = p.longitude_deg;
    pick->right_ascension_deg = p.right_ascension_deg;
    pick->declination_deg = p.declination_deg;
    pick->effective_radiance = p.effective_radiance_W_cm2_sr;
    pick->temperature_K = p.temperature_K;
    if (count_out) *count_out = n;
    if (wavelengths_um && spectral_radiance) {
      std::copy(p.wavelengths_um.begin(), p.wavelengths_um.end(), wavelengths_um);
      std::copy(p.spectral_radiance_W_cm2_sr_um.begin(), p.spectral_radiance_W_cm2_sr_um.end(), spectral_radiance);
    }
  });
}
}

EOIR_API eoir_status eoir_pick_term_get(eoir_engine engine, const char* sensor, int32_t space, uint32_t x, uint32_t y,
                                        int32_t term, double* values, size_t capacity, size_t* count_out) {
  return with_engine(engine, [&](Engine& e) {
    const std::string name = str(sensor, "sensor");
    if (term < EOIR_PICK_TERM_SURFACE || term > EOIR_PICK_TERM_AT_SENSOR)
      throw Error(Status::out_of_range, "term: " + std::to_string(term) + " is not an eoir_pick_term (0-5)");
    const scene::Pick p = e.pick(name, space, x, y);
    const scene::Eq9Terms& t = p.terms;
    const std::vector<double>* chosen[] = {&t.surface,      &t.downwelling,  &t.transmittance,
                                           &t.path_thermal, &t.path_scatter, &t.at_sensor};
    const std::vector<double>& v = *chosen[term];
    if (count_out) *count_out = v.size();
    if (!values) return;
    if (capacity < v.size()) throw Error(Status::buffer_too_small, "capacity: " + std::to_string(v.size()) + " values needed");
    std::copy(v.begin(), v.end(), values);
  });
}
