#include "universe/material.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/read_file.hpp"
#include "universe/json_document.hpp"
#include "universe/sensor_parameters.hpp"

namespace eoir::universe {
namespace {
using nlohmann::json;

[[noreturn]] void corrupt(const std::string& where, const std::string& what) {
  throw Error(Status::corrupt_file, where + ": " + what);
}

double number(const json& j, const std::string& key, const std::string& where) {
  if (!j.contains(key)) corrupt(where + "." + key, "missing");
  if (!j.at(key).is_number()) corrupt(where + "." + key, "expected a number");
  const double v = j.at(key).get<double>();
  if (!std::isfinite(v)) corrupt(where + "." + key, "not finite");
  return v;
}

// An optional field of text (grid, extension, brdf.reason).
void optional_string(const json& j, const std::string& key, const std::string& where) {
  if (j.contains(key) && !j.at(key).is_string()) corrupt(where + key, "expected a string");
}

// schemas/material.schema.json's name pattern ^[a-z0-9_]+$, at most 63 bytes
// as every name of the engine.
bool is_material_name(const std::string& name) {
  if (name.empty() || name.size() > 63) return false;
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
  return true;
}

std::vector<double> numbers(const json& j, const std::string& key, const std::string& where) {
  if (!j.contains(key) || !j.at(key).is_array()) corrupt(where + "." + key, "expected an array of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < j.at(key).size(); ++i) {
    const json& x = j.at(key)[i];
    const std::string at = where + "." + key + "[" + std::to_string(i) + "]";
    if (!x.is_number()) corrupt(at, "expected a number");
    out.push_back(x.get<double>());
    if (!std::isfinite(out.back())) corrupt(at, "not finite");
  }
  return out;
}
}  // namespace

void validate(const BrdfParameters& b, const std::string& field) {
  const struct {
    const char* name;
    double value, max;
  } checks[] = {{"k0", b.k0, 1.0}, {"k1", b.k1, 1.0}, {"alpha", b.alpha, BrdfParameters::max_sharpness},
                {"beta", b.beta, BrdfParameters::max_sharpness}};
  for (const auto& c : checks)
    if (!std::isfinite(c.value) || c.value < 0 || c.value > c.max)
      throw Error(Status::out_of_range, field + "." + c.name + ": must be in [0, " + number_text(c.max) + "], got " +
                                            number_text(c.value));
}

Material material_from_json(const json& doc, const std::string& origin) {
  if (!doc.is_object()) corrupt(origin, "expected a JSON object");
  static const char* known[] = {"format", "version", "name", "description", "sources", "brdf", "wavelength_um",
                                "reflectance", "grid", "extension", "composition"};
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    bool ok = false;
    for (const char* k : known) ok = ok || it.key() == k;
    if (!ok) corrupt(origin + ": " + it.key(), "unknown field");
  }
  if (!doc.contains("format") || !doc["format"].is_string() || doc["format"].get<std::string>() != "eoir-material")
    corrupt(origin + ": format", "must be \"eoir-material\"");
  if (!doc.contains("version") || !doc["version"].is_number_integer() || doc["version"].get<int>() != 1)
    throw Error(Status::file_version, origin + ": version: this engine reads material format version 1");
  Material m;
  if (!doc.contains("name") || !doc["name"].is_string() || doc["name"].get<std::string>().empty())
    corrupt(origin + ": name", "expected a non-empty string");
  m.name = doc["name"].get<std::string>();
  if (!is_material_name(m.name))
    corrupt(origin + ": name", "must be 1 to 63 of a-z, 0-9 and _ (schemas/material.schema.json)");
  if (m.name == gray_body_material) corrupt(origin + ": name", "gray_body is built in");
  if (m.name == lunar_gray_body_material) corrupt(origin + ": name", "lunar_gray_body is built in");
  optional_string(doc, "grid", origin + ": ");
  optional_string(doc, "extension", origin + ": ");
  if (doc.contains("composition")) {
    // Metadata of combined materials, checked as the schema has it.
    const json& c = doc["composition"];
    if (!c.is_array()) corrupt(origin + ": composition", "expected an array of {component, fraction}");
    for (std::size_t i = 0; i < c.size(); ++i) {
      const std::string at = origin + ": composition[" + std::to_string(i) + "]";
      if (!c[i].is_object() || c[i].size() != 2 || !c[i].contains("component") || !c[i]["component"].is_string())
        corrupt(at, "expected {\"component\": string, \"fraction\": number}");
      const double f = number(c[i], "fraction", at);
      if (f < 0 || f > 1) corrupt(at + ".fraction", "must be in [0, 1], got " + number_text(f));
    }
  }
  if (doc.contains("description")) {
    if (!doc["description"].is_string()) corrupt(origin + ": description", "expected a string");
    m.description = doc["description"].get<std::string>();
  }
  if (doc.contains("sources")) {
    if (!doc["sources"].is_array()) corrupt(origin + ": sources", "expected an array of strings");
    for (std::size_t i = 0; i < doc["sources"].size(); ++i) {
      const json& s = doc["sources"][i];
      if (!s.is_string()) corrupt(origin + ": sources[" + std::to_string(i) + "]", "expected a string");
      m.sources.push_back(s.get<std::string>());
    }
  }
  if (m.sources.empty()) corrupt(origin + ": sources", "name where the data come from");
  if (!doc.contains("brdf") || !doc["brdf"].is_object()) corrupt(origin + ": brdf", "missing");
  const json& b = doc["brdf"];
  const std::string where = origin + ": brdf";
  optional_string(b, "reason", where + ".");
  if (b.contains("model")) {  // only the lunar law is named; eq. 1 is the default
    if (!b["model"].is_string() || b["model"].get<std::string>() != lunar_brdf_model_name)
      corrupt(where + ".model", std::string("expected \"") + lunar_brdf_model_name + "\"");
    for (auto it = b.begin(); it != b.end(); ++it)
      if (it.key() != "model" && it.key() != "reason")
        corrupt(where + "." + it.key(), "unknown field (the lunar model has no parameters)");
    m.brdf.model = BrdfModel::lunar_lommel_seeliger;
  } else {
  for (auto it = b.begin(); it != b.end(); ++it)
    if (it.key() != "k0" && it.key() != "k1" && it.key() != "alpha" && it.key() != "beta" && it.key() != "reason")
      corrupt(where + "." + it.key(), "unknown field");
  m.brdf = BrdfParameters{number(b, "k0", where), number(b, "k1", where), number(b, "alpha", where),
                          number(b, "beta", where)};
  try {
    validate(m.brdf, where);
  } catch (const Error& e) {
    throw Error(Status::corrupt_file, e.what());  // names the file and the field
  }
  // A file's lobes have a sharpness (the schema's exclusiveMinimum; a flat
  // lobe is k0's part).
  if (!(m.brdf.alpha > 0)) corrupt(where + ".alpha", "must be > 0 (the forward lobe's sharpness), got 0");
  if (!(m.brdf.beta > 0)) corrupt(where + ".beta", "must be > 0 (the backscatter lobe's sharpness), got 0");
  }
  const std::vector<double> wl = numbers(doc, "wavelength_um", origin + ":");
  const std::vector<double> r = numbers(doc, "reflectance", origin + ":");
  if (wl.size() != r.size())
    corrupt(origin + ": reflectance", "has " + std::to_string(r.size()) + " values for " + std::to_string(wl.size()) +
                                          " wavelengths");
  for (std::size_t i = 0; i < r.size(); ++i)
    if (r[i] < 0 || r[i] > 1)
      corrupt(origin + ": reflectance[" + std::to_string(i) + "]", "must be in [0, 1], got " + number_text(r[i]));
  for (std::size_t i = 0; i < wl.size(); ++i)
    if (!(wl[i] > 0) || (i > 0 && !(wl[i] > wl[i - 1])))
      corrupt(origin + ": wavelength_um[" + std::to_string(i) + "]", "wavelengths must be positive and increase");
  // The table covers every band a sensor may take: outside it the SRF would
  // be 0 (black, emissivity 1) without a word.
  const std::string band = number_text(sensor_bounds::min_band_um) + "-" + number_text(sensor_bounds::max_band_um) +
                           " um (the bands a sensor may take)";
  if (!wl.empty() && !(wl.front() <= sensor_bounds::min_band_um))
    corrupt(origin + ": wavelength_um[0]", number_text(wl.front()) + " um: the table must cover " + band);
  if (!wl.empty() && !(wl.back() >= sensor_bounds::max_band_um))
    corrupt(origin + ": wavelength_um[" + std::to_string(wl.size() - 1) + "]",
            number_text(wl.back()) + " um: the table must cover " + band);
  try {
    m.reflectance = TabulatedFunction(wl, r, origin + ": reflectance");
  } catch (const Error& e) {
    corrupt(origin, e.what());
  }
  return m;
}

Material load_material(const std::string& path) {
  // 16 MiB: a material on the common grid is about 10 kB.
  const std::string text = read_file(path, std::size_t{16} << 20, "material files");
  return material_from_json(parse_json_document(text, path), path);
}

json material_to_json(const Material& m) {
  return json{{"format", "eoir-material"},
              {"version", 1},
              {"name", m.name},
              {"description", m.description},
              {"sources", m.sources},
              {"brdf", m.brdf.model == BrdfModel::lunar_lommel_seeliger
                           ? json{{"model", lunar_brdf_model_name}}
                           : json{{"k0", m.brdf.k0}, {"k1", m.brdf.k1}, {"alpha", m.brdf.alpha}, {"beta", m.brdf.beta}}},
              {"wavelength_um", m.reflectance.wavelengths_um()},
              {"reflectance", m.reflectance.values()}};
}

MaterialLibrary::MaterialLibrary() {
  Material gray;
  gray.name = gray_body_material;
  gray.description = "Gray body: spectrally flat SRF from the object's reflectance property, Lambertian";
  gray.sources = {"built in (spec 7.3 \"Gray Body\")"};
  gray.gray_body = true;
  materials_[gray.name] = std::make_shared<const Material>(gray);
  Material lunar = gray;
  lunar.name = lunar_gray_body_material;
  lunar.description = "Gray body with the lunar Lommel-Seeliger surface law (radiometry/disk_photometry.hpp): "
                      "the Moon's albedo map in bitmap mode, its SRF the normal albedo";
  lunar.sources = {"built in (Allen 1973 lunar phase law on a Lommel-Seeliger surface)"};
  lunar.brdf.model = BrdfModel::lunar_lommel_seeliger;
  materials_[lunar.name] = std::make_shared<const Material>(lunar);
}

void MaterialLibrary::load_directory(const std::string& dir) {
  std::error_code ec;
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  if (ec) throw Error(Status::io, "materials: cannot list '" + dir + "': " + ec.message());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) add(load_material(f));
}

void MaterialLibrary::add(const Material& material) {
  materials_[material.name] = std::make_shared<const Material>(material);
}

const Material* MaterialLibrary::find(const std::string& name) const {
  auto it = materials_.find(name);
  return it == materials_.end() ? nullptr : it->second.get();
}

const Material& MaterialLibrary::get(const std::string& name, const std::string& field) const {
  if (const Material* m = find(name)) return *m;
  std::string list;
  for (const auto& [n, m] : materials_) list += (list.empty() ? "" : ", ") + n;
  throw Error(Status::unknown_name, field + ": unknown material '" + name + "' (known: " + list + ")");
}

std::vector<std::string> MaterialLibrary::names() const {
  std::vector<std::string> out;
  for (const auto& [n, m] : materials_) out.push_back(n);
  return out;
}

}  // namespace eoir::universe
