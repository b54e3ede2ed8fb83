#include "universe/materials.hpp"

#include "core/error.hpp"

namespace eoir::universe {

const std::vector<const char*>& material_names() {
  static const std::vector<const char*> names = {
      "gray_body",          "aluminum",           "burnished_aluminum",    "aluminum_mli",
      "gold",               "gold_mli",           "silver",                "silver_mli",
      "solar_panel",        "black_thermal_control", "white_thermal_control", "mixed_forest_camouflage",
      "soil_camouflage",    "water_camouflage",
  };
  return names;
}

void check_material(const std::string& name, const std::string& field) {
  for (const char* m : material_names())
    if (name == m) return;
  std::string list;
  for (const char* m : material_names()) list += std::string(list.empty() ? "" : ", ") + m;
  throw Error(Status::unknown_name, field + ": unknown material '" + name + "' (known: " + list + ")");
}
}  // namespace eoir::universe
