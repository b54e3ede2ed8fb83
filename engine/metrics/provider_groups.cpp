#include "metrics/provider_groups.hpp"

#include "core/error.hpp"
#include "metrics/atmospheric_path.hpp"

namespace eoir::metrics {
namespace {
const GroupSpec& target_group() {
  static GroupSpec g{target_group_name, true,
                           {
                               {"Range to Target", ElementType::number, "km", ""},
                               {"Effective Target Irradiance", ElementType::number, "W/cm^2", ""},
                               {"Point Target Solid Angle", ElementType::number, "sr", ""},
                               {"Scene Photon NEI", ElementType::number, "W/cm^2", ""},
                               {"Total NEI", ElementType::number, "W/cm^2", ""},
                               {"Effective Target Radiance", ElementType::number, "W/(cm^2 sr)", ""},
                               {"Effective Background Radiance", ElementType::number, "W/(cm^2 sr)", ""},
                               {"Scene Photon NER", ElementType::number, "W/(cm^2 sr)", ""},
                               {"Total NER", ElementType::number, "W/(cm^2 sr)", ""},
                               {"Signal to Noise Ratio", ElementType::number, "", ""},
                               {"Geometric IFOV Footprint", ElementType::number, "m^2", ""},
                               {"Effective IFOV Footprint", ElementType::number, "m^2", ""},
                               {"Target Is Point Source", ElementType::boolean, "", ""},
                           }};
  static const bool with_path = [] {  // the atmosphere between them (metrics/atmospheric_path.hpp)
    for (const ElementSpec& e : atmospheric_path_elements()) g.elements.push_back(e);
    return true;
  }();
  (void)with_path;
  return g;
}
}  // namespace

const std::vector<GroupSpec>& provider_groups() {
  static const std::vector<GroupSpec> all = [] {
    std::vector<GroupSpec> v = static_provider_groups();
    v.push_back(target_group());
    return v;
  }();
  return all;
}

const GroupSpec& provider_group(const std::string& group) {
  for (const auto& g : provider_groups())
    if (group == g.name) return g;
  throw Error(Status::unknown_name, "group: unknown data provider group '" + group + "'");
}

ElementValue target_element(const TargetMetrics& t, const std::string& e) {
  auto number = [](double v) { return ElementValue{ElementType::number, v, nullptr}; };
  if (e == "Range to Target") return number(t.range_km);
  if (e == "Effective Target Irradiance") return number(t.effective_target_irradiance_W_cm2);
  if (e == "Point Target Solid Angle") return number(t.point_target_solid_angle_sr);
  if (e == "Scene Photon NEI") return number(t.scene_photon_nei_W_cm2);
  if (e == "Total NEI") return number(t.total_nei_W_cm2);
  if (e == "Effective Target Radiance") return number(t.effective_target_radiance_W_cm2_sr);
  if (e == "Effective Background Radiance") return number(t.effective_background_radiance_W_cm2_sr);
  if (e == "Scene Photon NER") return number(t.scene_photon_ner_W_cm2_sr);
  if (e == "Total NER") return number(t.total_ner_W_cm2_sr);
  if (e == "Signal to Noise Ratio") return number(t.snr);
  if (e == "Geometric IFOV Footprint") return number(t.geometric_ifov_footprint_m2);
  if (e == "Effective IFOV Footprint") return number(t.effective_ifov_footprint_m2);
  if (e == "Target Is Point Source") return ElementValue{ElementType::boolean, t.point_source ? 1.0 : 0.0, nullptr};
  throw Error(Status::unknown_name,
              "element: unknown element '" + e + "' of group '" + std::string(target_group_name) + "'");
}

}  // namespace eoir::metrics
