#include "universe/shapes.hpp"

#include <cmath>

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
      {"composite", {}},  // parts in the object's `composite` property (universe/composite.hpp)
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

}  // namespace eoir::universe
