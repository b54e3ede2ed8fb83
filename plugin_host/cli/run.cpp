#include "run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <array>
#include <system_error>

#include <sys/statvfs.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "fits_writer.hpp"
#include "iso_time.hpp"
#include "png_writer.hpp"
#include "session.hpp"
#include "suggest.hpp"

#ifndef EOIR_CLI_VERSION
#define EOIR_CLI_VERSION "0.0.0"
#endif

namespace eoir::cli {
namespace {

using ojson = nlohmann::ordered_json;
namespace fs = std::filesystem;
namespace io = eoir::imageio;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
// Pixel units in FITS unit syntax (FITS 4.0 section 4.3; astropy reads both).
constexpr const char* kBunitRadiance = "W cm-2 sr-1";
constexpr const char* kBunitElectrons = "electron";
constexpr const char* kBunitAdu = "adu";

struct Stats {
  double min = 0, max = 0, mean = 0;
  std::size_t non_finite = 0;
};

Stats stats_of(const std::vector<double>& v) {
  Stats s;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
  std::size_t n = 0;
  for (double x : v) {
    if (!std::isfinite(x)) {
      ++s.non_finite;
      continue;
    }
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    sum += x;
    ++n;
  }
  if (n == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.min = s.max = s.mean = nan;
  } else {
    s.min = lo;
    s.max = hi;
    s.mean = sum / static_cast<double>(n);
  }
  return s;
}

ojson stats_json(const Stats& s) {
  const auto num = [](double x) { return std::isfinite(x) ? ojson(x) : ojson(nullptr); };
  return {{"min", num(s.min)}, {"max", num(s.max)}, {"mean", num(s.mean)}, {"non_finite", s.non_finite}};
}

class RunContext {
 public:
  RunContext(Engine& engine, const Scenario& sc) : engine_(engine), sc_(sc) {}

  double number(const std::string& object, const char* property) const {
    double v = 0;
    engine_.check(engine_.api().get_number(engine_.handle(), object.c_str(), property, &v),
                  object + "." + property);
    return v;
  }

  // The sensor's fidelity knobs (README "Fidelity"), in the engine's order.
  nlohmann::ordered_json fidelity(const std::string& sensor) const {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const PropertyInfo& p : engine_.properties(sensor))
      if (p.fidelity) out[p.name] = engine_.value(sensor, p.name, p.type);
    return out;
  }

  // The settings the last frame of `sensor` was rendered with: the sensor's
  // knobs, or those its error_budget chose, with the error estimate
  // (eoir_frame_fidelity_get; the sensor's knobs from an older library).
  nlohmann::ordered_json frame_fidelity(const std::string& sensor) const {
    const eoir_api_v1& api = engine_.api();
    if (api.struct_size < offsetof(eoir_api_v1, frame_fidelity_get) + sizeof api.frame_fidelity_get)
      return fidelity(sensor);
    std::size_t length = 0;
    engine_.check(api.frame_fidelity_get(engine_.handle(), sensor.c_str(), nullptr, 0, &length), sensor + ".fidelity");
    std::string text(length + 1, '\0');
    engine_.check(api.frame_fidelity_get(engine_.handle(), sensor.c_str(), text.data(), text.size(), &length),
                  sensor + ".fidelity");
    text.resize(length);
    return nlohmann::ordered_json::parse(text);
  }

  // Whether the last frame kept its scene images (a frame made in strips
  // does not: its scene display is EOIR_ERR_NO_STATE).
  bool has_scene_images(const std::string& sensor, const std::string& where) const {
    eoir_image_info in{};
    in.struct_size = sizeof in;
    const eoir_status st = engine_.api().image_info_get(engine_.handle(), sensor.c_str(), EOIR_IMAGE_SCENE_DISPLAY, &in);
    if (st == EOIR_ERR_NO_STATE) return false;
    engine_.check(st, where + ": scene display");
    return true;
  }

  eoir_image_info info(const std::string& sensor, int32_t kind, const std::string& where) const {
    eoir_image_info in{};
    in.struct_size = sizeof in;
    engine_.check(engine_.api().image_info_get(engine_.handle(), sensor.c_str(), kind, &in), where);
    if (in.width == 0 || in.height == 0)
      throw EngineError(where + ": the engine reports an empty image (" + std::to_string(in.width) + "x" +
                            std::to_string(in.height) + ")",
                        EOIR_ERR_INTERNAL);
    return in;
  }

  std::vector<double> values(const std::string& sensor, int32_t kind, const eoir_image_info& in,
                             const std::string& where) const {
    std::vector<double> v(static_cast<std::size_t>(in.width) * in.height);
    engine_.check(engine_.api().image_get(engine_.handle(), sensor.c_str(), kind, v.data(), v.size()), where);
    return v;
  }

  // The detector stage's ADU image (C ABI 1.7), if the frame has one: the
  // electron image's info carries the ADC's range only then.
  bool has_adu(const eoir_image_info& electrons) const {
    const eoir_api_v1& api = engine_.api();
    return electrons.adc_max_adu > 0 &&
           api.struct_size >= offsetof(eoir_api_v1, image_get_adu) + sizeof api.image_get_adu &&
           api.image_get_adu != nullptr;
  }
  std::vector<std::uint32_t> adu(const std::string& sensor, const eoir_image_info& in, const std::string& where) const {
    std::vector<std::uint32_t> v(static_cast<std::size_t>(in.width) * in.height);
    engine_.check(engine_.api().image_get_adu(engine_.handle(), sensor.c_str(), v.data(), v.size()), where);
    return v;
  }

  std::vector<std::uint8_t> bytes(const std::string& sensor, int32_t kind, const eoir_image_info& in,
                                  const std::string& where) const {
    std::vector<std::uint8_t> v(static_cast<std::size_t>(in.width) * in.height);
    engine_.check(engine_.api().image_get_bytes(engine_.handle(), sensor.c_str(), kind, v.data(), v.size()), where);
    return v;
  }

  // Per-frame truth (eoir_truth_count/get): every object in the field of
  // the last frame, as a JSON array (schemas/truth.schema.json).
  // J2000 position of an object at the engine time (metres).
  std::array<double, 3> j2000_position(const std::string& name, const std::string& where) const {
    eoir_state st{};
    st.struct_size = sizeof st;
    st.frame = EOIR_FRAME_J2000;
    engine_.check(engine_.api().object_get_state(engine_.handle(), name.c_str(), &st), where + ": state of " + name);
    return {st.position[0], st.position[1], st.position[2]};
  }

  ojson truth(const std::string& sensor, const std::string& where, const eoir_image_info& pixels) const {
    const eoir_api_v1& api = engine_.api();
    if (api.struct_size < offsetof(eoir_api_v1, truth_get) + sizeof api.truth_get || api.truth_count == nullptr ||
        api.truth_get == nullptr)
      throw EngineError(where + ": the engine library has no per-frame truth (C ABI 1.2 needed)", EOIR_ERR_ABI_MISMATCH);
    std::size_t n = 0;
    engine_.check(api.truth_count(engine_.handle(), sensor.c_str(), &n), where);
    // C ABI 1.3 truth: kind, apparent RA/Dec, magnitudes, streak ends.
    const bool v13 = api.struct_size >= offsetof(eoir_api_v1, target_spectrum_get) + sizeof api.target_spectrum_get &&
                     api.target_spectrum_get != nullptr;
    // C ABI 1.5 truth: topocentric azimuth and elevation, air mass.
    const bool v15 = api.struct_size >= offsetof(eoir_api_v1, sensor_point_at) + sizeof api.sensor_point_at;
    // C ABI 1.6 truth: astrometric and geometric directions, the integration's start and end.
    const bool v16 = api.struct_size >= offsetof(eoir_api_v1, pick_term_get) + sizeof api.pick_term_get;
    const std::string times[3] = {v16 ? iso_of(pixels.start_jd_utc) : "", iso_of(pixels),
                                  v16 ? iso_of(pixels.end_jd_utc) : ""};
    const auto num = [](double x) { return std::isfinite(x) ? ojson(x) : ojson(nullptr); };
    ojson out = ojson::array();
    for (std::size_t k = 0; k < n; ++k) {
      eoir_truth t{};
      t.struct_size = sizeof t;
      engine_.check(api.truth_get(engine_.handle(), sensor.c_str(), k, &t), where + " [" + std::to_string(k) + "]");
      t.object[sizeof t.object - 1] = '\0';
      ojson o;
      o["object"] = std::string(t.object);
      o["pixel_x"] = num(t.pixel_x);
      o["pixel_y"] = num(t.pixel_y);
      // FITS pixel convention: 1-based, centre of the first pixel = 1.0, row
      // 1 at the bottom (the FITS files are written bottom row first).
      o["x_fits"] = num(t.pixel_x + 1.0);
      o["y_fits"] = num(static_cast<double>(pixels.height) - t.pixel_y);
      if (v16) {
        // Astrometric (ICRS: the FITS WCS's frame) at the middle, start and
        // end of the integration; apparent and geometric (eoir.h).
        o["kind"] = t.kind == EOIR_TRUTH_STAR ? "star" : "object";
        o["ra_deg"] = num(t.astrometric_ra_deg);
        o["dec_deg"] = num(t.astrometric_dec_deg);
        o["time"] = times[1];
        o["start_time"] = times[0];
        o["start_ra_deg"] = num(t.start_astrometric_ra_deg);
        o["start_dec_deg"] = num(t.start_astrometric_dec_deg);
        o["end_time"] = times[2];
        o["end_ra_deg"] = num(t.end_astrometric_ra_deg);
        o["end_dec_deg"] = num(t.end_astrometric_dec_deg);
        o["apparent_ra_deg"] = num(t.right_ascension_deg);
        o["apparent_dec_deg"] = num(t.declination_deg);
        o["geometric_ra_deg"] = num(t.geometric_ra_deg);
        o["geometric_dec_deg"] = num(t.geometric_dec_deg);
      } else if (v13) {
        // The engine's direction (the apparent place of stars, the Moon and planets).
        o["kind"] = t.kind == EOIR_TRUTH_STAR ? "star" : "object";
        o["ra_deg"] = num(t.right_ascension_deg);
        o["dec_deg"] = num(t.declination_deg);
      } else {
        // Geometric J2000 direction from the sensor to the object.
        const std::string name(t.object);
        const auto target = j2000_position(name, where);
        const auto self = j2000_position(sensor, where);
        const double dx = target[0] - self[0], dy = target[1] - self[1], dz = target[2] - self[2];
        double ra = std::atan2(dy, dx) / kDeg;
        if (ra < 0) ra += 360.0;
        o["kind"] = "object";
        o["ra_deg"] = num(ra);
        o["dec_deg"] = num(std::atan2(dz, std::hypot(dx, dy)) / kDeg);
      }
      o["range_m"] = num(t.range_m);
      o["point_source"] = t.point_source != 0;
      o["visible"] = t.visible != 0;
      o["effective_irradiance"] = num(t.effective_irradiance);
      o["effective_radiance"] = num(t.effective_radiance);
      o["snr"] = num(t.snr);
      if (v13 && t.kind == EOIR_TRUTH_STAR) {
        o["v_mag"] = num(t.v_mag);
        o["b_v_mag"] = num(t.b_v_mag);
      }
      // Only from sensors within 100 km of the Earth's surface.
      if (v15 && t.topocentric) {
        o["azimuth_deg"] = num(t.azimuth_deg);
        o["elevation_deg"] = num(t.elevation_deg);
      }
      if (v15) o["air_mass"] = num(t.air_mass);  // 0 while the atmosphere is off
      // The streak (start and end of the integration) in FITS pixels.
      const double sx = v13 ? t.start_pixel_x : t.pixel_x, sy = v13 ? t.start_pixel_y : t.pixel_y;
      const double ex = v13 ? t.end_pixel_x : t.pixel_x, ey = v13 ? t.end_pixel_y : t.pixel_y;
      o["start_fits"] = {num(sx + 1.0), num(static_cast<double>(pixels.height) - sy)};
      o["end_fits"] = {num(ex + 1.0), num(static_cast<double>(pixels.height) - ey)};
      out.push_back(std::move(o));
    }
    return out;
  }

  std::string iso_of(const double (&jd_utc)[2]) const {
    eoir_time t{};
    t.scale = EOIR_TIME_UTC;
    t.jd1 = jd_utc[0];
    t.jd2 = jd_utc[1];
    char buf[64];
    engine_.check(engine_.api().time_to_iso(&t, buf, sizeof buf), "image time");
    return buf;
  }
  // The frame time: the middle of the integration.
  std::string iso_of(const eoir_image_info& in) const { return iso_of(in.time_jd_utc); }

  static double mjd_of(const double (&jd_utc)[2]) { return (jd_utc[0] - 2400000.5) + jd_utc[1]; }

  // The engine's image info carries the frame's times, observer and
  // astrometric WCS from C ABI 1.6 on.
  void need_v16(const std::string& where) const {
    const eoir_api_v1& api = engine_.api();
    if (api.struct_size < offsetof(eoir_api_v1, pick_term_get) + sizeof api.pick_term_get)
      throw EngineError(where + ": the engine library has no astrometric WCS and exposure times (C ABI 1.6 needed)",
                        EOIR_ERR_ABI_MISMATCH);
  }

  // FITS dates carry no time-zone letter (FITS 4.0 section 9.1.1; the time
  // scale is TIMESYS).
  static std::string fits_time(std::string iso) {
    if (!iso.empty() && (iso.back() == 'Z' || iso.back() == 'z')) iso.pop_back();
    return iso;
  }

  // Header common to every FITS file of a frame; SAMPPIX is the image's
  // samples per sensor pixel (the sensor's samples_per_pixel for the scene,
  // 1 for the sensor images).
  io::FitsHeader header(const SensorSpec& s, std::size_t index, const eoir_image_info& in, const char* kind_name,
                        const char* bunit, double cube_step_s = 0.0) const {
    need_v16("FITS header of " + s.name);
    const long long pixels = engine_.value(s.name, "horizontal_pixels", EOIR_TYPE_INTEGER).get<long long>();
    const long long samples_per_pixel = pixels > 0 ? static_cast<long long>(in.width) / pixels : 1;
    io::FitsHeader h;
    // Times (FITS 4.0 section 9; Rots et al. 2015, A&A 574, A36): DATE-OBS
    // is the start of the integration, as DATE-BEG; DATE-AVG its middle (the
    // engine's frame time); UTC at the observer (TREFPOS).
    const std::string begin = fits_time(iso_of(in.start_jd_utc));
    h.set_string("DATE-OBS", begin, "start of the integration (UTC)");
    h.set_string("DATE-BEG", begin, "start of the integration (UTC)");
    h.set_string("DATE-AVG", fits_time(iso_of(in)), "middle of the integration (UTC)");
    h.set_string("DATE-END", fits_time(iso_of(in.end_jd_utc)), "end of the integration (UTC)");
    h.set_string("TIMESYS", "UTC", "time scale of the DATE and MJD cards");
    h.set_string("TREFPOS", "TOPOCENTER", "times at the sensor (OBSGEO)");
    h.set_double("MJD-OBS", mjd_of(in.start_jd_utc), "[d] DATE-OBS as MJD (UTC)");
    h.set_double("MJD-BEG", mjd_of(in.start_jd_utc), "[d] DATE-BEG as MJD (UTC)");
    h.set_double("MJD-AVG", mjd_of(in.time_jd_utc), "[d] DATE-AVG as MJD (UTC)");
    h.set_double("MJD-END", mjd_of(in.end_jd_utc), "[d] DATE-END as MJD (UTC)");
    h.set_double("EXPTIME", number(s.name, "integration_time_ms") / 1000.0, "[s] integration time");
    // The observer at DATE-AVG: ITRS position (FITS 4.0 sections 8.4.1,
    // 9.3.2: one set of coordinates, the Cartesian one); for an observer that
    // is not a site, also its J2000 (GCRS) state, in cards of our own.
    static const char* const axis[3] = {"X", "Y", "Z"};
    for (int k = 0; k < 3; ++k)
      h.set_double(std::string("OBSGEO-") + axis[k], in.observer_earth_fixed_m[k],
                   std::string("[m] sensor ITRS ") + axis[k] + " at DATE-AVG");
    const ObjectSpec* parent = sc_.find_object(s.parent);
    if (parent == nullptr || parent->kind != "site") {
      for (int k = 0; k < 3; ++k)
        h.set_double(std::string("OBSJ2K-") + axis[k], in.observer_position_m[k],
                     std::string("[m] sensor J2000 (GCRS) ") + axis[k] + " at DATE-AVG");
      for (int k = 0; k < 3; ++k)
        h.set_double(std::string("OBSJ2KV") + axis[k], in.observer_velocity_m_s[k],
                     std::string("[m/s] sensor J2000 (GCRS) v") + axis[k] + " at DATE-AVG");
    }
    h.set_string("BUNIT", bunit, "unit of the pixel values");
    // The electron images' detector cards, where they apply.
    const bool electrons = std::string(bunit) == kBunitElectrons;
    const bool with_noise = std::string(kind_name).rfind("sensor_electrons", 0) == 0;  // and its cube
    if (electrons) h.set_double("GAIN", 1.0, "[electron/adu] the pixel values are electrons");
    if (electrons && with_noise && in.saturation_electrons > 0)
      h.set_double("SATURATE", in.saturation_electrons, "[electron] saturation level");
    if (electrons && with_noise && in.read_noise_electrons > 0)
      h.set_double("RDNOISE", in.read_noise_electrons, "[electron] dark (read) noise sigma");
    // The ADU image of the detector stage (README "Detector model").
    if (std::string(bunit) == kBunitAdu) {
      h.set_double("GAIN", in.gain_e_per_adu, "[electron/adu] conversion gain");
      if (in.read_noise_electrons > 0) h.set_double("RDNOISE", in.read_noise_electrons, "[electron] read noise sigma");
      h.set_double("SATURATE", in.saturation_adu, "[adu] a full well (at most DATAMAX)");
      h.set_double("DATAMAX", in.adc_max_adu, "[adu] the ADC's largest value, 2^bits - 1");
      h.set_double("BIASLEV", in.bias_adu, "[adu] bias added before the ADC");
    }
    h.set_string("INSTRUME", s.name, "EOIR sensor");
    h.set_string("SENSOR", s.name, "EOIR sensor name");
    h.set_string("PARENT", s.parent, "object carrying the sensor");
    h.set_string("SCENARIO", sc_.name, "scenario name");
    h.set_integer("FRAME", static_cast<long long>(index), "time-step index of this run (0-based)");
    h.set_string("IMAGTYPE", kind_name, "EOIR image kind");
    h.set_integer("SAMPPIX", samples_per_pixel, "image samples per sensor pixel along each axis");
    h.set_double("BORE_RA", in.boresight_ra_deg, "[deg] J2000 RA of the sensor +z (boresight)");
    h.set_double("BORE_DEC", in.boresight_dec_deg, "[deg] J2000 Dec of the sensor +z (boresight)");
    h.set_double("UP_RA", in.up_ra_deg, "[deg] J2000 RA of the sensor +y (image up)");
    h.set_double("UP_DEC", in.up_dec_deg, "[deg] J2000 Dec of the sensor +y (image up)");
    h.set_double("BANDLO", number(s.name, "band_low_um"), "[um] band lower edge");
    h.set_double("BANDHI", number(s.name, "band_high_um"), "[um] band upper edge");
    // The engine's astrometric TAN WCS (ICRS as a plate solution against a
    // star catalogue gives it) at the image centre. Its CD matrix is per
    // image column and row (rows down); the writer flips rows so that FITS
    // pixel (1,1) is the lower left, so the FITS y derivatives change sign.
    io::FitsPointing wcs;
    wcs.ra_deg = in.astrometric_ra_deg;
    wcs.dec_deg = in.astrometric_dec_deg;
    wcs.crpix1 = (static_cast<double>(in.width) + 1.0) / 2.0;  // the boresight: image centre
    wcs.crpix2 = (static_cast<double>(in.height) + 1.0) / 2.0;
    wcs.cd1_1 = in.astrometric_cd_deg[0];
    wcs.cd1_2 = -in.astrometric_cd_deg[1];
    wcs.cd2_1 = in.astrometric_cd_deg[2];
    wcs.cd2_2 = -in.astrometric_cd_deg[3];
    wcs.radesys = "ICRS";  // astrometric: the frame of the star catalogue
    wcs.time_step_s = cube_step_s;
    wcs.mjdref = mjd_of(in.time_jd_utc);
    wcs.dateref = fits_time(iso_of(in));
    io::add_tan_pointing(h, wcs);
    // The fidelity of the frame, as HIERARCH FID <property> cards.
    const nlohmann::ordered_json knobs = frame_fidelity(s.name);
    for (auto it = knobs.begin(); it != knobs.end(); ++it) {
      const std::string key = "FID " + it.key();
      const nlohmann::ordered_json& v = it.value();
      if (v.is_string()) h.set_string(key, v.get<std::string>(), "fidelity");
      else if (v.is_number_integer()) h.set_integer(key, v.get<long long>(), "fidelity");
      else if (v.is_boolean()) h.set_logical(key, v.get<bool>(), "fidelity");
      else if (v.is_number()) h.set_double(key, v.get<double>(), "fidelity");
    }
    h.set_string("ORIGIN", "eoir " EOIR_CLI_VERSION, "eoir run");
    return h;
  }

  // Mean pixel pitch at the boresight, degrees (the astrometric WCS's).
  static double pixel_scale_deg(const eoir_image_info& in) {
    const double* cd = in.astrometric_cd_deg;
    return std::sqrt(std::fabs(cd[0] * cd[3] - cd[1] * cd[2]));
  }

  // ADU: unsigned 16-bit integers (BZERO 32768) up to 16-bit ADCs, 32-bit (BZERO 2^31) beyond.
  void write_fits(const std::string& path, const std::vector<std::uint32_t>& v, const eoir_image_info& in,
                  const io::FitsHeader& h) const {
    io::FitsWriteOptions o;
    o.pixel_type = in.adc_max_adu <= 65535.0 ? io::FitsPixelType::UInt16 : io::FitsPixelType::UInt32;
    io::write_fits_image(path, v.data(), in.width, in.height, h, o);
  }

  void write_fits(const std::string& path, const std::vector<double>& v, const eoir_image_info& in,
                  const io::FitsHeader& h) const {
    io::FitsWriteOptions o;
    o.pixel_type = io::FitsPixelType::Float32;
    io::write_fits_image(path, v.data(), in.width, in.height, h, o);
  }

 private:
  Engine& engine_;
  const Scenario& sc_;
};

// A ds9 region file of a frame's truth: a labelled circle (3 pixels) at each
// object's RA/Dec in ICRS, green if visible, red if hidden behind another;
// catalogue stars in yellow.
std::string region_text(const ojson& truth, const std::string& sensor, const std::string& time, double radius_deg) {
  std::string out = "# Region file format: DS9 version 4.1\n";
  out += "# eoir run: truth of " + sensor + " at " + time + " (circles of 3 pixels at the objects' RA/Dec)\n";
  out += "global color=green width=1 font=\"helvetica 10 normal roman\" select=1 edit=1 move=1 delete=1 "
         "include=1 source=1\nicrs\n";
  char line[512];
  for (const auto& t : truth) {
    if (!t["ra_deg"].is_number() || !t["dec_deg"].is_number()) continue;
    std::string name = t["object"].get<std::string>();
    for (char& c : name)
      if (c == '{' || c == '}' || c == '\n') c = '_';
    const bool visible = t["visible"].get<bool>();
    const bool star = t.contains("kind") && t["kind"] == "star";
    std::snprintf(line, sizeof line, "circle(%.9f,%.9f,%.4f\") # text={%s}%s\n", t["ra_deg"].get<double>(),
                  t["dec_deg"].get<double>(), radius_deg * 3600.0, name.c_str(),
                  star ? " color=yellow" : visible ? "" : " color=red");
    out += line;
  }
  return out;
}

// The data cube of one sensor, streamed (never held whole): its FITS file
// (a temporary beside the target) is opened at the sensor's first frame with
// NAXIS3 = the run's time steps, each frame's electrons are written as their
// plane when rendered, and the TIMES table, the checksums and the rename
// follow the last frame. A run that fails before then leaves no cube.
struct CubeStream {
  io::FitsCubeWriter writer;
  std::int64_t width = 0, height = 0;
  std::vector<std::string> starts, middles;  // DATE-OBS (the start) and DATE-AVG of each plane
  std::vector<double> mjd_starts, mjd_middles, boresight_ra, boresight_dec, up_ra, up_dec;
};

// --cube's disk-space check: the cube's float32 pixels against the space
// free for an unprivileged user on the file system of --out.
void check_cube_space(const std::string& dir, const std::string& sensor, std::int64_t width, std::int64_t height,
                      std::size_t planes) {
  struct statvfs fs_info {};
  if (::statvfs(dir.c_str(), &fs_info) != 0) return;  // unknown: let the write report it
  const double need_bytes =
      4.0 * static_cast<double>(width) * static_cast<double>(height) * static_cast<double>(planes);
  const double free_bytes = static_cast<double>(fs_info.f_bavail) * static_cast<double>(fs_info.f_frsize);
  if (need_bytes > free_bytes) {
    const auto size_text = [](double bytes) {
      char t[32];
      if (bytes >= 1073741824.0) std::snprintf(t, sizeof t, "%.3g GiB", bytes / 1073741824.0);
      else std::snprintf(t, sizeof t, "%.3g MiB", bytes / 1048576.0);
      return std::string(t);
    };
    char text[512];
    std::snprintf(text, sizeof text,
                  "--cube: the data cube of %s (%zu planes of %lld x %lld float32) needs %s, but the file system of "
                  "--out '%s' has %s free; free space, use fewer time steps or run without --cube",
                  sensor.c_str(), planes, static_cast<long long>(width), static_cast<long long>(height),
                  size_text(need_bytes).c_str(), dir.c_str(), size_text(free_bytes).c_str());
    throw std::runtime_error(text);
  }
}

// The fraction of the sensor pixels at the saturation level (0 with
// saturation off).
double saturated_fraction(const std::vector<double>& electrons, const eoir_image_info& in) {
  if (!(in.saturation_electrons > 0) || electrons.empty()) return 0.0;
  const auto n = std::count_if(electrons.begin(), electrons.end(),
                               [&](double e) { return e >= in.saturation_electrons; });
  return static_cast<double>(n) / static_cast<double>(electrons.size());
}

// What a reader of a frame should know before looking at it: nothing in the
// field (no object or star in the truth, and the scene's radiance uniform
// to 1e-9), or more than half of the pixels saturated.
ojson frame_warnings(const ojson& truth, const std::vector<double>& radiance, const std::vector<double>& electrons,
                     const eoir_image_info& in) {
  ojson out = ojson::array();
  const Stats r = stats_of(radiance);
  if (!radiance.empty() && truth.empty() && r.non_finite == 0 && r.max - r.min <= 1e-9 * std::fabs(r.max)) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "nothing in the field: no object or star, and a uniform scene (radiance %.6g W cm-2 sr-1)", r.max);
    out.push_back(text);
  }
  const double saturated = saturated_fraction(electrons, in);
  if (saturated > 0.5) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "%.1f %% of the pixels are saturated (%.6g electrons); shorten integration_time_ms or raise the "
                  "saturation level",
                  100.0 * saturated, in.saturation_electrons);
    out.push_back(text);
  }
  return out;
}

std::string format_duration(double s) {
  char buf[32];
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1f s", s);
  else if (s < 3600) std::snprintf(buf, sizeof buf, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  else std::snprintf(buf, sizeof buf, "%dh%02dm", static_cast<int>(s) / 3600, static_cast<int>(s) / 60 % 60);
  return buf;
}

void make_out_dir(const std::string& dir) {
  if (dir.empty()) throw std::runtime_error("--out: empty directory name");
  std::error_code ec;
  const fs::path p(dir);
  if (fs::exists(p, ec) && !fs::is_directory(p, ec))
    throw std::runtime_error("--out: '" + dir + "' exists and is not a directory");
  fs::create_directories(p, ec);
  if (ec) throw std::runtime_error("--out: cannot create directory '" + dir + "': " + ec.message());
  if (!fs::is_directory(p, ec)) throw std::runtime_error("--out: '" + dir + "' is not a directory");
  if (access(dir.c_str(), W_OK | X_OK) != 0)
    throw std::runtime_error("--out: directory '" + dir + "' is not writable");
}

void write_text_atomically(const std::string& path, const std::string& text) {
  try {
    io::write_file_atomically(path, text.data(), text.size());
  } catch (const io::ImageIoError& e) {
    throw std::runtime_error("cannot write " + fs::path(path).filename().string() + ": " + e.what());
  }
}

std::size_t write_frames(Engine& engine, const Scenario& sc, const RunOptions& opt,
                         const std::vector<const SensorSpec*>& sensors) {
  Session session(engine, sc);
  RunContext ctx(engine, sc);

  const std::size_t total = opt.times.size() * sensors.size();
  const auto began = std::chrono::steady_clock::now();
  const bool tty = isatty(fileno(stderr)) != 0;
  ojson frames = ojson::array();
  std::size_t done = 0;
  const fs::path dir(opt.out_dir);

  // --stretch: every sensor's display stretch (the engine checks the name).
  if (!opt.stretch.empty())
    for (const SensorSpec* s : sensors)
      engine.check(engine.api().set_string(engine.handle(), s->name.c_str(), "display_stretch", opt.stretch.c_str()),
                   "--stretch " + opt.stretch + " (sensor " + s->name + ")");

  std::map<std::string, CubeStream> cubes;
  std::set<std::string> strips_noted;  // sensors whose frames are made in strips, said once
  const double cube_step_s = opt.times.size() > 1 ? opt.times[1] - opt.times[0] : 1.0;

  for (std::size_t i = 0; i < opt.times.size(); ++i) {
    session.set_time(opt.times[i]);
    for (const SensorSpec* s : sensors) {
      const std::string where = "render " + s->name + " at " + format_iso(opt.times[i]);
      engine.check(engine.api().render(engine.handle(), s->name.c_str()), where);

      char index_text[32];
      std::snprintf(index_text, sizeof index_text, "%04zu", i);
      const std::string base = file_stem(s->name) + "_" + index_text + "_";
      const std::string f_rad = base + "radiance.fits", f_el = base + "electrons.fits",
                        f_mean = base + "mean_electrons.fits", f_scene = base + "scene.png",
                        f_sensor = base + "sensor.png", f_truth = base + "truth.json", f_adu = base + "adu.fits",
                        f_region = base + "truth.reg";

      const eoir_image_info in_rad = ctx.info(s->name, EOIR_IMAGE_SCENE_RADIANCE, where + ": scene radiance");
      const eoir_image_info in_el = ctx.info(s->name, EOIR_IMAGE_SENSOR_ELECTRONS, where + ": sensor electrons");
      const eoir_image_info in_mean = ctx.info(s->name, EOIR_IMAGE_SENSOR_MEAN, where + ": sensor mean");
      const eoir_image_info in_pd = ctx.info(s->name, EOIR_IMAGE_SENSOR_DISPLAY, where + ": sensor display");
      // A frame made in strips (the sensor's scene_memory_max_mib) keeps no
      // scene images: its scene radiance FITS and PNG are not written.
      const bool scene_images = ctx.has_scene_images(s->name, where);
      if (!scene_images && strips_noted.insert(s->name).second && !opt.quiet)
        std::fprintf(stderr,
                     "%seoir run: note: %s's frames are made in strips (their buffers exceed its "
                     "scene_memory_max_mib): no scene radiance FITS and no scene PNG\n",
                     tty ? "\r\033[K" : "", s->name.c_str());
      const std::vector<double> rad =
          scene_images ? ctx.values(s->name, EOIR_IMAGE_SCENE_RADIANCE, in_rad, where + ": scene radiance")
                       : std::vector<double>{};
      const std::vector<double> el = ctx.values(s->name, EOIR_IMAGE_SENSOR_ELECTRONS, in_el, where + ": electrons");
      const std::vector<double> mean = ctx.values(s->name, EOIR_IMAGE_SENSOR_MEAN, in_mean, where + ": mean");
      eoir_image_info in_sd{};
      std::vector<std::uint8_t> sd;
      if (scene_images) {
        in_sd = ctx.info(s->name, EOIR_IMAGE_SCENE_DISPLAY, where + ": scene display");
        sd = ctx.bytes(s->name, EOIR_IMAGE_SCENE_DISPLAY, in_sd, where + ": display");
      }
      const std::vector<std::uint8_t> pd = ctx.bytes(s->name, EOIR_IMAGE_SENSOR_DISPLAY, in_pd, where + ": display");

      const bool with_adu = ctx.has_adu(in_el);
      const ojson truth = ctx.truth(s->name, where + ": truth", in_el);
      const ojson warnings = frame_warnings(truth, rad, el, in_el);
      for (const auto& w : warnings)
        std::fprintf(stderr, "%seoir run: warning: %s frame %zu (%s): %s\n", tty ? "\r\033[K" : "", s->name.c_str(), i,
                     ctx.iso_of(in_el).c_str(), w.get<std::string>().c_str());
      try {
        if (scene_images)
          ctx.write_fits((dir / f_rad).string(), rad, in_rad,
                         ctx.header(*s, i, in_rad, "scene_radiance", kBunitRadiance));
        ctx.write_fits((dir / f_el).string(), el, in_el,
                       ctx.header(*s, i, in_el, "sensor_electrons", kBunitElectrons));
        ctx.write_fits((dir / f_mean).string(), mean, in_mean,
                       ctx.header(*s, i, in_mean, "sensor_mean", kBunitElectrons));
        if (with_adu) {
          const eoir_image_info in_adu = ctx.info(s->name, EOIR_IMAGE_SENSOR_ADU, where + ": sensor ADU");
          ctx.write_fits((dir / f_adu).string(), ctx.adu(s->name, in_adu, where + ": ADU"), in_adu,
                         ctx.header(*s, i, in_adu, "sensor_adu", kBunitAdu));
        }
        if (scene_images) io::write_png_gray8((dir / f_scene).string(), sd.data(), in_sd.width, in_sd.height);
        io::write_png_gray8((dir / f_sensor).string(), pd.data(), in_pd.width, in_pd.height);
        const std::string truth_text = truth.dump(2) + "\n";
        io::write_file_atomically((dir / f_truth).string(), truth_text.data(), truth_text.size());
        const std::string region =
            region_text(truth, s->name, ctx.iso_of(in_el), RunContext::pixel_scale_deg(in_el));
        io::write_file_atomically((dir / f_region).string(), region.data(), region.size());
      } catch (const io::ImageIoError& e) {
        throw std::runtime_error(std::string("cannot write frame ") + index_text + " of " + s->name + ": " +
                                 e.what());
      }

      if (opt.cube) {
        CubeStream& c = cubes[s->name];
        const std::string cube_name = file_stem(s->name) + "_electrons_cube.fits";
        try {
          if (!c.writer.is_open()) {
            // The header is the first frame's (its pointing, times and fidelity).
            check_cube_space(opt.out_dir, s->name, in_el.width, in_el.height, opt.times.size());
            io::FitsHeader h = ctx.header(*s, 0, in_el, "sensor_electrons_cube", kBunitElectrons,
                                          cube_step_s > 0 ? cube_step_s : 1.0);
            h.set_integer("NFRAMES", static_cast<long long>(opt.times.size()), "frames in the cube (NAXIS3)");
            h.add_comment(
                "Plane k (1-based) is time step k-1 of the run; its time and pointing are in the TIMES table.");
            h.add_comment("The celestial WCS is the first plane's.");
            io::FitsWriteOptions o;
            o.pixel_type = io::FitsPixelType::Float32;
            c.width = in_el.width;
            c.height = in_el.height;
            c.writer.open((dir / cube_name).string(), c.width, c.height, static_cast<std::int64_t>(opt.times.size()),
                          h, o);
          }
          if (in_el.width != c.width || in_el.height != c.height)
            throw io::ImageIoError("frame " + std::string(index_text) + " is " + std::to_string(in_el.width) +
                                   " x " + std::to_string(in_el.height) + " pixels, the cube's planes " +
                                   std::to_string(c.width) + " x " + std::to_string(c.height));
          c.writer.write_plane(static_cast<std::int64_t>(i), el.data());
        } catch (const io::ImageIoError& e) {
          throw std::runtime_error("cannot write the data cube of " + s->name + ": " + e.what());
        }
        c.starts.push_back(RunContext::fits_time(ctx.iso_of(in_el.start_jd_utc)));
        c.middles.push_back(RunContext::fits_time(ctx.iso_of(in_el)));
        c.mjd_starts.push_back(RunContext::mjd_of(in_el.start_jd_utc));
        c.mjd_middles.push_back(RunContext::mjd_of(in_el.time_jd_utc));
        c.boresight_ra.push_back(in_el.boresight_ra_deg);
        c.boresight_dec.push_back(in_el.boresight_dec_deg);
        c.up_ra.push_back(in_el.up_ra_deg);
        c.up_dec.push_back(in_el.up_dec_deg);
      }

      ojson fr;
      fr["index"] = i;
      fr["time"] = ctx.iso_of(in_el);
      fr["start_time"] = ctx.iso_of(in_el.start_jd_utc);
      fr["end_time"] = ctx.iso_of(in_el.end_jd_utc);
      fr["sensor"] = s->name;
      fr["files"] = {{"radiance", f_rad},   {"electrons", f_el},  {"mean_electrons", f_mean},
                     {"scene_png", f_scene}, {"sensor_png", f_sensor}, {"truth", f_truth},
                     {"regions", f_region}};
      if (with_adu) fr["files"]["adu"] = f_adu;
      if (!scene_images) {
        fr["files"].erase("radiance");
        fr["files"].erase("scene_png");
      }
      fr["scene_size"] = {{"width", in_rad.width}, {"height", in_rad.height}};
      fr["sensor_size"] = {{"width", in_el.width}, {"height", in_el.height}};
      fr["boresight_ra_deg"] = in_el.boresight_ra_deg;
      fr["boresight_dec_deg"] = in_el.boresight_dec_deg;
      fr["up_ra_deg"] = in_el.up_ra_deg;
      fr["up_dec_deg"] = in_el.up_dec_deg;
      fr["electrons"] = stats_json(stats_of(el));
      fr["mean_electrons"] = stats_json(stats_of(mean));
      if (scene_images) fr["radiance"] = stats_json(stats_of(rad));
      fr["saturated_fraction"] = saturated_fraction(el, in_el);
      fr["warnings"] = warnings;
      frames.push_back(std::move(fr));

      ++done;
      if (!opt.quiet) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
        const double eta = elapsed / static_cast<double>(done) * static_cast<double>(total - done);
        std::fprintf(stderr, "%seoir run: frame %zu of %zu (%s, %s), elapsed %s, ETA %s%s", tty ? "\r\033[K" : "",
                     done, total, s->name.c_str(), format_iso(opt.times[i]).c_str(),
                     format_duration(elapsed).c_str(), format_duration(eta).c_str(), tty ? "" : "\n");
        std::fflush(stderr);
      }
    }
  }
  if (!opt.quiet && tty) std::fprintf(stderr, "\n");

  // Data cubes: every frame of a sensor as one image (NAXIS3 = time step) with
  // the first frame's pointing and a linear time axis; a TIMES table gives
  // each plane's exact time and pointing (a moving sensor changes it).
  ojson cube_files = ojson::object();
  for (const SensorSpec* s : sensors) {
    if (!opt.cube) break;
    CubeStream& c = cubes.at(s->name);
    io::FitsTable table;
    table.extname = "TIMES";
    std::vector<double> frame_index;
    for (std::size_t k = 0; k < c.starts.size(); ++k) frame_index.push_back(static_cast<double>(k));
    table.columns = {{"FRAME", "", frame_index, {}},          {"DATE-OBS", "", {}, c.starts},
                     {"DATE-AVG", "", {}, c.middles},         {"MJD-OBS", "d", c.mjd_starts, {}},
                     {"MJD-AVG", "d", c.mjd_middles, {}},     {"BORE_RA", "deg", c.boresight_ra, {}},
                     {"BORE_DEC", "deg", c.boresight_dec, {}}, {"UP_RA", "deg", c.up_ra, {}},
                     {"UP_DEC", "deg", c.up_dec, {}}};
    try {
      c.writer.finish(table);
    } catch (const io::ImageIoError& e) {
      throw std::runtime_error("cannot write the data cube of " + s->name + ": " + e.what());
    }
    cube_files[s->name] = file_stem(s->name) + "_electrons_cube.fits";
  }

  ojson sensors_json = ojson::array();
  for (const SensorSpec* s : sensors) {
    ojson entry = {{"name", s->name}, {"parent", s->parent}};
    entry["fidelity"] = ctx.fidelity(s->name);
    sensors_json.push_back(std::move(entry));
  }
  ojson summary;
  summary["format"] = "eoir-run-summary";
  summary["version"] = 1;
  summary["scenario"] = sc.name;
  summary["scenario_file"] = opt.scenario_file;
  summary["start"] = format_iso(opt.times.front());
  summary["stop"] = format_iso(opt.times.back());
  summary["time_steps"] = opt.times.size();
  summary["sensors"] = sensors_json;
  summary["units"] = {{"radiance", kBunitRadiance}, {"electrons", kBunitElectrons}};
  summary["frames"] = frames;
  if (opt.cube) summary["cubes"] = cube_files;
  summary["complete"] = true;
  if (!opt.save_state.empty()) {
    engine.check(engine.api().state_save(engine.handle(), opt.save_state.c_str()), "--save-state " + opt.save_state);
    if (!opt.quiet) std::fprintf(stderr, "eoir run: saved the engine state to %s\n", opt.save_state.c_str());
  }
  write_text_atomically((dir / "summary.json").string(), summary.dump(2) + "\n");  // last
  if (!opt.quiet)
    std::fprintf(stderr, "eoir run: wrote %zu frames to %s (summary.json)\n", done, opt.out_dir.c_str());
  return done;
}


}  // namespace

io::FitsHeader frame_fits_header(Engine& engine, const Scenario& sc, const SensorSpec& s, std::size_t index,
                                 int32_t kind) {
  RunContext ctx(engine, sc);
  const std::string where = "FITS header of " + s.name;
  const eoir_image_info in = ctx.info(s.name, kind, where);
  switch (kind) {
    case EOIR_IMAGE_SCENE_RADIANCE:
      return ctx.header(s, index, in, "scene_radiance", kBunitRadiance);
    case EOIR_IMAGE_SENSOR_ELECTRONS:
      return ctx.header(s, index, in, "sensor_electrons", kBunitElectrons);
    case EOIR_IMAGE_SENSOR_MEAN:
      return ctx.header(s, index, in, "sensor_mean", kBunitElectrons);
    case EOIR_IMAGE_SENSOR_ADU:
      return ctx.header(s, index, in, "sensor_adu", kBunitAdu);
    default:
      throw EngineError(where + ": image kind " + std::to_string(kind) + " is not written to FITS",
                        EOIR_ERR_OUT_OF_RANGE);
  }
}

std::string frame_truth_json(Engine& engine, const Scenario& sc, const std::string& sensor) {
  RunContext ctx(engine, sc);
  const std::string where = "truth of " + sensor;
  const eoir_image_info in = ctx.info(sensor, EOIR_IMAGE_SENSOR_ELECTRONS, where);
  return ctx.truth(sensor, where, in).dump(2) + "\n";
}

std::string file_stem(const std::string& name) {
  std::string out = name;
  for (char& c : out) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' ||
                    c == '_' || c == '-';
    if (!ok) c = '_';
  }
  if (out.empty() || out[0] == '.') out.insert(out.begin(), '_');
  return out;
}

std::size_t run_frames(Engine& engine, const Scenario& sc, const RunOptions& opt) {
  // Which sensors, in scenario order (or the order given).
  std::vector<const SensorSpec*> sensors;
  if (opt.sensors.empty()) {
    for (const SensorSpec& s : sc.sensors) sensors.push_back(&s);
  } else {
    for (const std::string& name : opt.sensors) {
      const SensorSpec* s = sc.find_sensor(name);
      if (s == nullptr) {
        std::string known;
        std::vector<std::string> names;
        for (const SensorSpec& k : sc.sensors) {
          known += (known.empty() ? "'" : ", '") + k.name + "'";
          names.push_back(k.name);
        }
        throw std::runtime_error("--sensor: unknown sensor '" + name + "' in " + opt.scenario_file +
                                 did_you_mean(name, names) + "; sensors: " + (known.empty() ? "(none)" : known));
      }
      if (std::find(sensors.begin(), sensors.end(), s) == sensors.end()) sensors.push_back(s);
    }
  }
  if (sensors.empty()) throw std::runtime_error(opt.scenario_file + ": the scenario has no sensors to render");
  // Two sensors must not share file names.
  for (std::size_t i = 0; i < sensors.size(); ++i)
    for (std::size_t j = i + 1; j < sensors.size(); ++j)
      if (file_stem(sensors[i]->name) == file_stem(sensors[j]->name))
        throw std::runtime_error("sensors '" + sensors[i]->name + "' and '" + sensors[j]->name +
                                 "' would write the same file names ('" + file_stem(sensors[i]->name) + "_...')");
  if (opt.times.size() > 9999)
    throw std::runtime_error("run: " + std::to_string(opt.times.size()) +
                             " time steps; at most 9999 per run (use a larger --step)");

  make_out_dir(opt.out_dir);
  // A reader tells a complete run from an interrupted or failed one (run.hpp):
  // INCOMPLETE exists until summary.json, written last, says "complete": true.
  // A summary left by an earlier run into the same folder goes first.
  const fs::path dir(opt.out_dir);
  const std::string marker = (dir / kIncompleteMarker).string();
  const std::string started = "eoir run of " + opt.scenario_file +
                              ": frames are being written here; this file is removed once summary.json is written "
                              "(\"complete\": true). A folder holding it is an interrupted or failed run.\n";
  write_text_atomically(marker, started);
  std::error_code ec;
  fs::remove(dir / "summary.json", ec);
  if (ec) throw std::runtime_error("cannot remove the earlier " + (dir / "summary.json").string() + ": " + ec.message());
  try {
    const std::size_t done = write_frames(engine, sc, opt, sensors);
    if (!fs::remove(marker, ec) || ec)
      throw std::runtime_error("cannot remove " + marker + (ec ? ": " + ec.message() : std::string()));
    return done;
  } catch (const std::exception& e) {
    try {
      write_text_atomically(marker, started + "failed: " + e.what() + "\n");
    } catch (const std::exception&) {
      // the marker stays as it was: still incomplete
    }
    throw;
  }
}


}  // namespace eoir::cli
