#include "metrics/static_providers.hpp"

#include <utility>

#include "core/error.hpp"

namespace eoir::metrics {
namespace {

using sensor::Curve;
using sensor::StaticMetrics;

// One element: its spec and the StaticMetrics field that holds its value.
struct Entry {
  ElementSpec spec;
  double StaticMetrics::*number = nullptr;
  std::int64_t StaticMetrics::*integer = nullptr;
  Curve StaticMetrics::*curve = nullptr;
};
struct Group {
  const char* name;
  std::vector<Entry> entries;
};

Entry number(const char* name, const char* unit, double StaticMetrics::*field) {
  return {{name, ElementType::number, unit, ""}, field, nullptr, nullptr};
}
Entry integer(const char* name, std::int64_t StaticMetrics::*field) {
  return {{name, ElementType::integer, "count", ""}, nullptr, field, nullptr};
}
Entry curve(const char* name, Curve StaticMetrics::*field) {
  return {{name, ElementType::curve, "", "cycles/mrad"}, nullptr, nullptr, field};
}

// Spec 5.12 Table 1, grouped as the report styles of spec 7.6 step 5.
const std::vector<Group>& catalogue() {
  using M = StaticMetrics;
  static const std::vector<Group> groups{
      {"EOIR Sensor Spatial Performance",
       {
           integer("Number of Horizontal Pixels", &M::horizontal_pixels),
           integer("Number of Vertical Pixels", &M::vertical_pixels),
           number("Horizontal FOV", "deg", &M::horizontal_fov_deg),
           number("Vertical FOV", "deg", &M::vertical_fov_deg),
           number("FOV Solid Angle", "sr", &M::fov_solid_angle_sr),
           number("Horizontal IFOV", "mrad", &M::horizontal_ifov_mrad),
           number("Vertical IFOV", "mrad", &M::vertical_ifov_mrad),
           number("IFOV Solid Angle", "sr", &M::ifov_solid_angle_sr),
           number("Effective Horizontal FOV", "deg", &M::effective_horizontal_fov_deg),
           number("Effective Vertical FOV", "deg", &M::effective_vertical_fov_deg),
           number("Effective FOV Solid Angle", "sr", &M::effective_fov_solid_angle_sr),
           number("Effective Horizontal IFOV", "mrad", &M::effective_horizontal_ifov_mrad),
           number("Effective Vertical IFOV", "mrad", &M::effective_vertical_ifov_mrad),
           number("Effective IFOV Solid Angle", "sr", &M::effective_ifov_solid_angle_sr),
       }},
      {"EOIR Sensor Spectral Performance",
       {
           number("Low Band Edge Wavelength", "um", &M::band_low_um),
           number("High Band Edge Wavelength", "um", &M::band_high_um),
           integer("Number of Spectral Intervals", &M::spectral_intervals),
       }},
      {"EOIR Radiometric Performance",
       {
           number("Integration Time", "ms", &M::integration_time_ms),
           number("Peak Radiance Responsivity", "e-/(W/(cm^2 sr))", &M::peak_radiance_responsivity),
           number("Peak Irradiance Responsivity", "e-/(W/cm^2)", &M::peak_irradiance_responsivity),
           number("Dark NEI", "W/cm^2", &M::dark_nei_W_cm2),
           number("Dark NER", "W/(cm^2 sr)", &M::dark_ner_W_cm2_sr),
           number("SEI", "W/cm^2", &M::sei_W_cm2),
           number("SER", "W/(cm^2 sr)", &M::ser_W_cm2_sr),
       }},
      {"EOIR Sensor Optics",
       {
           number("Effective Focal Length", "cm", &M::focal_length_cm),
           number("F-number", "", &M::f_number),
           number("Entrance Pupil Diameter", "cm", &M::entrance_pupil_diameter_cm),
           number("Diffraction Wavelength", "um", &M::diffraction_wavelength_um),
           number("Airy Disk Diameter", "mrad", &M::airy_disk_diameter_mrad),
           number("Rayleigh Resolution", "mrad", &M::rayleigh_resolution_mrad),
           number("Sparrow Resolution", "mrad", &M::sparrow_resolution_mrad),
           number("Ensquared Energy", "", &M::ensquared_energy),
           curve("Diffraction OTF", &M::diffraction_otf),
           curve("Optics OTF", &M::optics_otf),
           curve("Jitter OTF", &M::jitter_otf),
           curve("Horizontal Detector Footprint MTF", &M::horizontal_detector_mtf),
           curve("Vertical Detector Footprint MTF", &M::vertical_detector_mtf),
       }},
  };
  return groups;
}

ElementValue read(const Entry& e, const StaticMetrics& m) {
  if (e.number != nullptr) return {ElementType::number, m.*(e.number), nullptr};
  if (e.integer != nullptr) return {ElementType::integer, static_cast<double>(m.*(e.integer)), nullptr};
  return {ElementType::curve, 0.0, &(m.*(e.curve))};
}

}  // namespace

const std::vector<GroupSpec>& static_provider_groups() {
  static const std::vector<GroupSpec> specs = [] {
    std::vector<GroupSpec> out;
    for (const Group& g : catalogue()) {
      GroupSpec spec{g.name, false, {}};
      for (const Entry& e : g.entries) spec.elements.push_back(e.spec);
      out.push_back(std::move(spec));
    }
    return out;
  }();
  return specs;
}

ElementValue static_element(const sensor::StaticMetrics& m, const std::string& group, const std::string& element) {
  for (const Group& g : catalogue()) {
    if (group != g.name) continue;
    for (const Entry& e : g.entries)
      if (element == e.spec.name) return read(e, m);
    throw Error(Status::unknown_name, "element: unknown element '" + element + "' of group '" + group + "'");
  }
  throw Error(Status::unknown_name, "group: unknown static group '" + group + "'");
}

}  // namespace eoir::metrics
