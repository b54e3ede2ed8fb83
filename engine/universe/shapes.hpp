// Simple shapes of spec 4.1.5.1 and the dimensions each takes (metres).
#pragma once
#include <string>
#include <vector>

namespace eoir::universe {

struct ShapeInfo {
  const char* name;
  std::vector<const char*> dimensions;  // meaning of each entry of dimensions_m
};

// sphere, oblate, box, plate, cylinder, cone, coupler, none, composite.
const std::vector<ShapeInfo>& shapes();
// Throws eoir::Error(unknown_name) naming `field` with the list of shapes.
const ShapeInfo& find_shape(const std::string& name, const std::string& field);
// Throws eoir::Error(out_of_range) unless dims fits the shape (count, > 0, finite).
void check_dimensions(const ShapeInfo& shape, const std::vector<double>& dims, const std::string& field);

}  // namespace eoir::universe
