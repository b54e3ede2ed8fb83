// Surface materials (spec 4.1.4.1, 4.3.3-4.3.5, Appendix A): a spectral
// reflectance function SRF(lambda) (emissivity 1 - SRF, opaque) and the four
// parameters of the BRDF of eq. 1. Materials are files in the data folder's
// materials/ (format schemas/material.schema.json) or a user's own file of
// the same format; gray_body is built in, its flat SRF the object's
// `reflectance` property, its BRDF Lambertian.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/tabulated_function.hpp"

namespace eoir::universe {

// The reflectance law of a surface: eq. 1 (spec 4.1.4.1), or the lunar
// Lommel-Seeliger surface (radiometry/disk_photometry.hpp), whose SRF is the
// normal albedo rather than the hemispherical reflectance.
enum class BrdfModel { modified_phong, lunar_lommel_seeliger };
constexpr const char* lunar_brdf_model_name = "lunar_lommel_seeliger";

// Eq. 1: k0 Lambertian fraction; k1 backscatter fraction of the rest;
// alpha, beta sharpness of the forward (specular) and backscatter lobes
// (unused by the lunar model).
struct BrdfParameters {
  double k0 = 1.0, k1 = 0.0, alpha = 0.0, beta = 0.0;  // Lambertian
  BrdfModel model = BrdfModel::modified_phong;
  static constexpr double max_sharpness = 1000.0;
};
// Throws out_of_range naming `field` (e.g. "burnished_aluminum.json: brdf.k0").
void validate(const BrdfParameters& brdf, const std::string& field);

struct Material {
  std::string name;
  std::string description;
  std::vector<std::string> sources;
  TabulatedFunction reflectance;  // SRF, 0..1
  BrdfParameters brdf;
  bool gray_body = false;         // SRF from the object's `reflectance` property
};

constexpr const char* gray_body_material = "gray_body";
// Built in as well: a gray body with the lunar surface law, for the Moon's
// albedo map (bitmap mode).
constexpr const char* lunar_gray_body_material = "lunar_gray_body";

// Parses one material document; `origin` names the file in messages.
// Throws eoir::Error(corrupt_file) naming the origin and field: missing,
// unknown or wrong-typed fields, names outside ^[a-z0-9_]+$ (63 bytes),
// NaN, non-monotonic wavelengths, tables not covering 0.28-28 um,
// reflectance outside [0, 1], BRDF parameters out of range (alpha and beta
// > 0).
Material material_from_json(const nlohmann::json& doc, const std::string& origin);
// The same from a file (io for a missing file, corrupt_file for bad content).
Material load_material(const std::string& path);
// The document material_from_json reads back as the same material (saved
// states carry the user's materials in it).
nlohmann::json material_to_json(const Material& material);

// The materials an engine knows: gray_body, the data folder's, the user's.
class MaterialLibrary {
 public:
  MaterialLibrary();  // gray_body only
  // Every *.json of a folder (throws naming the first bad file).
  void load_directory(const std::string& dir);
  // Adds or replaces (by name).
  void add(const Material& material);
  // nullptr if unknown.
  const Material* find(const std::string& name) const;
  // Throws unknown_name naming `field` and listing the known materials.
  const Material& get(const std::string& name, const std::string& field) const;
  std::vector<std::string> names() const;

 private:
  std::map<std::string, std::shared_ptr<const Material>> materials_;
};

}  // namespace eoir::universe
