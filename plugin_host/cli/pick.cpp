#include "pick.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "iso_time.hpp"
#include "session.hpp"
#include "suggest.hpp"

namespace eoir::cli {
namespace {

constexpr const char* kRadianceUnit = "W/(cm^2 sr um)";

std::string sensor_list(const Scenario& sc) {
  std::string known;
  for (const SensorSpec& s : sc.sensors) known += (known.empty() ? "'" : ", '") + s.name + "'";
  return known.empty() ? "(none)" : known;
}

// One vector of the grid size: asks the size, then reads (values may grow
// between the calls only if the frame changed, which it does not here).
template <typename Read>
std::vector<double> read_vector(const Engine& engine, const std::string& where, Read read) {
  std::size_t n = 0;
  engine.check(read(nullptr, 0, &n), where);
  std::vector<double> v(n);
  engine.check(read(v.data(), v.size(), &n), where);
  v.resize(n);
  return v;
}

nlohmann::ordered_json number(double x) { return std::isfinite(x) ? nlohmann::ordered_json(x) : nullptr; }

std::string where_text(const PickOptions& opt) {
  return std::string(opt.pixel ? "pixel" : "sample") + " (" + std::to_string(opt.x) + ", " + std::to_string(opt.y) +
         ")";
}

}  // namespace

PickTerms pick_terms(Engine& engine, const Scenario& sc, const PickOptions& opt) {
  if (sc.find_sensor(opt.sensor) == nullptr) {
    std::vector<std::string> names;
    for (const SensorSpec& s : sc.sensors) names.push_back(s.name);
    throw PickArgumentError("--sensor: unknown sensor '" + opt.sensor + "' in " + opt.scenario_file +
                            did_you_mean(opt.sensor, names) + "; sensors: " + sensor_list(sc));
  }
  const eoir_api_v1& api = engine.api();
  if (api.struct_size < offsetof(eoir_api_v1, pick_term_get) + sizeof api.pick_term_get ||
      api.pick_term_get == nullptr)
    throw std::runtime_error(std::string("the engine library ") + engine.library_path() +
                             " has no eq. 9 terms for picks (C ABI 1.6 needed)");
  Session session(engine, sc);
  session.set_time(opt.time_s);
  const std::string iso = format_iso(opt.time_s);
  const char* sensor = opt.sensor.c_str();
  engine.check(api.render(engine.handle(), sensor), "render " + opt.sensor + " at " + iso);

  // The frame's size in samples or pixels, so that a bad x or y names the option.
  eoir_image_info info{};
  info.struct_size = sizeof info;
  engine.check(api.image_info_get(engine.handle(), sensor,
                                  opt.pixel ? EOIR_IMAGE_SENSOR_ELECTRONS : EOIR_IMAGE_SCENE_RADIANCE, &info),
               "frame of " + opt.sensor);
  const char* what = opt.pixel ? "pixels" : "scene samples";
  if (opt.x >= info.width)
    throw PickArgumentError("--x: " + std::to_string(opt.x) + " is outside the frame of sensor '" + opt.sensor +
                            "' (" + std::to_string(info.width) + " " + what + " across: 0-" +
                            std::to_string(info.width - 1) + ")");
  if (opt.y >= info.height)
    throw PickArgumentError("--y: " + std::to_string(opt.y) + " is outside the frame of sensor '" + opt.sensor +
                            "' (" + std::to_string(info.height) + " " + what + " down: 0-" +
                            std::to_string(info.height - 1) + ")");

  const int32_t space = opt.pixel ? 1 : 0;
  const std::string where = "pick of " + opt.sensor + " at " + where_text(opt);
  PickTerms p;
  p.pick.struct_size = sizeof p.pick;
  std::vector<double> radiance;
  p.wavelength_um = read_vector(engine, where, [&](double* values, std::size_t capacity, std::size_t* n) {
    radiance.resize(capacity);
    return api.pick_get(engine.handle(), sensor, space, opt.x, opt.y, &p.pick, values,
                        values != nullptr ? radiance.data() : nullptr, capacity, n);
  });
  for (std::size_t term = 0; term < kPickTermNames.size(); ++term) {
    p.terms[term] = read_vector(engine, where + ", term " + kPickTermNames[term],
                                [&](double* values, std::size_t capacity, std::size_t* n) {
                                  return api.pick_term_get(engine.handle(), sensor, space, opt.x, opt.y,
                                                           static_cast<int32_t>(term), values, capacity, n);
                                });
    if (p.terms[term].size() != p.wavelength_um.size())
      throw std::runtime_error(where + ": term " + kPickTermNames[term] + " has " +
                               std::to_string(p.terms[term].size()) + " values for " +
                               std::to_string(p.wavelength_um.size()) + " intervals");
  }
  return p;
}

std::string pick_csv(const Scenario& sc, const PickOptions& opt, const PickTerms& p) {
  std::ostringstream out;
  char line[512];
  out << "# eoir pick: scenario '" << sc.name << "' (" << opt.scenario_file << "), sensor " << opt.sensor << ", "
      << where_text(opt) << ", " << format_iso(opt.time_s) << "\n";
  const eoir_pick& k = p.pick;
  if (k.hit != 0)
    std::snprintf(line, sizeof line, "# hit: %s (patch %d), range %.3f m, temperature %.6g K\n", k.object, k.patch,
                  k.range_m, k.temperature_K);
  else
    std::snprintf(line, sizeof line, "# hit: sky, RA %.6f deg, Dec %.6f deg\n", k.right_ascension_deg,
                  k.declination_deg);
  out << line;
  if (k.has_geodetic != 0) {
    std::snprintf(line, sizeof line, "# latitude %.6f deg, longitude %.6f deg\n", k.latitude_deg, k.longitude_deg);
    out << line;
  }
  std::snprintf(line, sizeof line, "# effective radiance: %.9g W/(cm^2 sr)\n", k.effective_radiance);
  out << line;
  out << "# units: wavelength_um um (interval centre); transmittance 1; the others " << kRadianceUnit << "\n";
  out << "# at_sensor = surface * transmittance + path_thermal + path_scatter (eq. 9); downwelling is part of "
         "surface\n";
  out << "wavelength_um";
  for (const char* name : kPickTermNames) out << "," << name;
  out << "\n";
  for (std::size_t i = 0; i < p.wavelength_um.size(); ++i) {
    std::snprintf(line, sizeof line, "%.17g", p.wavelength_um[i]);
    out << line;
    for (const auto& term : p.terms) {
      std::snprintf(line, sizeof line, ",%.17g", term[i]);
      out << line;
    }
    out << "\n";
  }
  return out.str();
}

std::string pick_json(const Scenario& sc, const PickOptions& opt, const PickTerms& p) {
  const eoir_pick& k = p.pick;
  nlohmann::ordered_json doc;
  doc["scenario"] = sc.name;
  doc["file"] = opt.scenario_file;
  doc["sensor"] = opt.sensor;
  doc["time"] = format_iso(opt.time_s);
  doc["space"] = opt.pixel ? "pixel" : "sample";
  doc["x"] = opt.x;
  doc["y"] = opt.y;
  doc["hit"] = k.hit != 0;
  doc["object"] = k.hit != 0 ? nlohmann::ordered_json(std::string(k.object)) : nullptr;
  doc["patch"] = k.patch;
  doc["range_m"] = number(k.range_m);
  doc["latitude_deg"] = k.has_geodetic != 0 ? number(k.latitude_deg) : nullptr;
  doc["longitude_deg"] = k.has_geodetic != 0 ? number(k.longitude_deg) : nullptr;
  doc["right_ascension_deg"] = number(k.right_ascension_deg);
  doc["declination_deg"] = number(k.declination_deg);
  doc["temperature_K"] = number(k.temperature_K);
  doc["effective_radiance_W_cm2_sr"] = number(k.effective_radiance);
  nlohmann::ordered_json units;
  units["wavelength_um"] = "um";
  for (const char* name : kPickTermNames) units[name] = std::string(name) == "transmittance" ? "1" : kRadianceUnit;
  doc["units"] = units;
  nlohmann::ordered_json columns;
  const auto column = [](const std::vector<double>& v) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (double x : v) a.push_back(number(x));
    return a;
  };
  columns["wavelength_um"] = column(p.wavelength_um);
  for (std::size_t t = 0; t < kPickTermNames.size(); ++t) columns[kPickTermNames[t]] = column(p.terms[t]);
  doc["columns"] = columns;
  return doc.dump(2) + "\n";
}

}  // namespace eoir::cli
