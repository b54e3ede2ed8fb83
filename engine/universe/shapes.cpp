#include "universe/shapes.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace eoir::universe {

const std::vector<ShapeInfo>& shapes() {
  static const std::vector<ShapeInfo> table = {
      {"sphere", {"radius"}},
      {"oblate", {"equatorial_radius", "polar_radius"}},
      {"box", {"length_x", "width_y", "height_z"}},
      {"plate", {"length_x", "width_y"}},
      {"cylinder", {"radius", "length"}},
      {"cone", {"base_radius", "length"}},
      {"coupler", {"base_radius", "top_radius", "length"}},
      {"none", {}},
  };
  return table;
}

const ShapeInfo& find_shape(const std::string& name, const std::string& field) {
  for (const auto& s : shapes())
    if (name == s.name) return s;
  std::string list;
  for (const auto& s : shapes()) list += std::string(list.empty() ? "" : ", ") + s.name;
  throw Error(Status::unknown_name, field + ": unknown shape '" + name + "' (known: " + list + ")");
}

void check_dimensions(const ShapeInfo& shape, const std::vector<double>& dims, const std::string& field) {
  if (dims.size() != shape.dimensions.size())
    throw Error(Status::out_of_range, field + ": shape '" + shape.name + "' takes " +
                                          std::to_string(shape.dimensions.size()) + " dimensions, got " +
                                          std::to_string(dims.size()));
  for (size_t i = 0; i < dims.size(); ++i)
    require_positive(dims[i], field + "[" + std::to_string(i) + "] (" + shape.dimensions[i] + ")");
}

double volumetric_radius_m(const ShapeInfo& shape, const std::vector<double>& d) {
  using constants::pi;
  const std::string n = shape.name;
  double volume = 0;
  if (n == "sphere") return d[0];
  if (n == "oblate") return std::cbrt(d[0] * d[0] * d[1]);
  if (n == "box") volume = d[0] * d[1] * d[2];
  if (n == "plate") return std::sqrt(d[0] * d[1] / (2.0 * pi));  // no volume: sphere of equal surface (both faces)
  if (n == "cylinder") volume = pi * d[0] * d[0] * d[1];
  if (n == "cone") volume = pi * d[0] * d[0] * d[1] / 3.0;
  if (n == "coupler") volume = pi * d[2] * (d[0] * d[0] + d[0] * d[1] + d[1] * d[1]) / 3.0;
  return std::cbrt(3.0 * volume / (4.0 * pi));
}
}  // namespace eoir::universe
