// The SNR access constraint and the per-frame truth (spec 5.13, 7.8).
#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstring>

#include "capi_internal.hpp"

using namespace eoir;
using eoir::capi::need;
using eoir::capi::str;
using eoir::capi::with_engine;

extern "C" {

EOIR_API eoir_status eoir_snr_constraint(eoir_engine engine, const char* sensor, const char* target,
                                         const eoir_time* time, double* snr_out) {
  return with_engine(engine, [&](Engine& e) {
    need(snr_out, "snr_out");
    const std::string s = str(sensor, "sensor"), t = str(target, "target");
    if (time) e.set_time(capi::time_of(time, "time"));
    *snr_out = e.target_metrics(s, t).snr;
  });
}

EOIR_API eoir_status eoir_target_spectrum_get(eoir_engine engine, const char* sensor, const char* target,
                                              double* wavelengths_um, double* irradiance_W_cm2_um, size_t capacity,
                                              size_t* count_out) {
  return with_engine(engine, [&](Engine& e) {
    need(count_out, "count_out");
    const std::string s = str(sensor, "sensor");
    const auto w = e.world(s);
    const std::vector<double> E = metrics::find_target(*w, e.universe(), str(target, "target")).point_spectral_irradiance();
    *count_out = E.size();
    if (!wavelengths_um || !irradiance_W_cm2_um) return;
    if (capacity < E.size())
      throw Error(Status::buffer_too_small, "capacity: " + std::to_string(E.size()) + " values needed");
    const auto& wl = w->spectral().sample_wavelengths_um;
    std::copy(wl.begin(), wl.end(), wavelengths_um);
    std::copy(E.begin(), E.end(), irradiance_W_cm2_um);
  });
}

EOIR_API eoir_status eoir_truth_count(eoir_engine engine, const char* sensor, size_t* count_out) {
  return with_engine(engine, [&](Engine& e) {
    need(count_out, "count_out");
    *count_out = e.truth(str(sensor, "sensor")).size();
  });
}

EOIR_API eoir_status eoir_truth_get(eoir_engine engine, const char* sensor, size_t index, eoir_truth* out) {
  return with_engine(engine, [&](Engine& e) {
    const auto& rows = e.truth(str(sensor, "sensor"));
    need(out, "truth_out");
    constexpr size_t v12_size = offsetof(eoir_truth, kind);  // the struct before 1.3 appended kind
    capi::need_size(out->struct_size, v12_size, "truth_out");
    if (index >= rows.size())
      throw Error(Status::out_of_range, "index: " + std::to_string(index) + " >= truth count " +
                                            std::to_string(rows.size()));
    const TruthEntry& row = rows[index];
    const metrics::TargetMetrics& t = row.metrics;
    const uint32_t size = out->struct_size;
    eoir_truth full{};
    full.struct_size = size;
    eoir_truth* const caller = out;
    out = &full;
    capi::copy_text(out->object, row.object);
    out->pixel_x = t.pixel_x;
    out->pixel_y = t.pixel_y;
    out->range_m = t.range_km * 1e3;
    out->point_source = t.point_source ? 1 : 0;
    out->visible = t.visible ? 1 : 0;
    out->effective_irradiance = t.effective_target_irradiance_W_cm2;
    out->effective_radiance = t.effective_target_radiance_W_cm2_sr;
    out->snr = t.snr;
    out->kind = row.kind == TruthEntry::Kind::star ? EOIR_TRUTH_STAR : EOIR_TRUTH_OBJECT;
    out->right_ascension_deg = row.ra_deg;
    out->declination_deg = row.dec_deg;
    out->v_mag = row.v_mag;
    out->b_v_mag = row.b_v_mag;
    out->start_pixel_x = row.start_x;
    out->start_pixel_y = row.start_y;
    out->end_pixel_x = row.end_x;
    out->end_pixel_y = row.end_y;
    out->topocentric = row.topocentric ? 1 : 0;
    out->azimuth_deg = row.azimuth_deg;
    out->elevation_deg = row.elevation_deg;
    out->air_mass = row.air_mass;
    out->astrometric_ra_deg = row.astrometric_ra_deg;
    out->astrometric_dec_deg = row.astrometric_dec_deg;
    out->start_astrometric_ra_deg = row.start_astrometric_ra_deg;
    out->start_astrometric_dec_deg = row.start_astrometric_dec_deg;
    out->end_astrometric_ra_deg = row.end_astrometric_ra_deg;
    out->end_astrometric_dec_deg = row.end_astrometric_dec_deg;
    out->geometric_ra_deg = row.geometric_ra_deg;
    out->geometric_dec_deg = row.geometric_dec_deg;
    std::memcpy(caller, &full, std::min<size_t>(size, sizeof full));  // what the caller's version holds
  });
}
}
