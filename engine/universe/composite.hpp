// Composite shapes (spec 4.1.5.1): simple shapes, or other composites, at
// given offsets and orientations. A composite object carries its parts as a
// JSON array in its `composite` property:
//   [{"shape": "box", "dimensions_m": [1, 1, 2], "offset_m": [0, 0, 0],
//     "orientation_wxyz": [1, 0, 0, 0], "temperature_K": 290, "reflectance": 0.1,
//     "material": "gold_mli"},
//    {"parts": [ ...nested parts... ], "offset_m": [0, 3, 0]},
//    {"shape": "mesh", "mesh_file": "bus.glb", "dimensions_m": [0.001],
//     "mesh_materials": {"panel": {"material": "solar_panel", "temperature_K": 320}}}]
// offset_m and orientation_wxyz (part -> parent) default to zero and
// identity; temperature_K, reflectance and material default to the parent's. An empty
// top-level array (the default) makes a composite that images nothing. The
// text is parsed once, when the property is set; a mesh part's file is read
// then (relative paths: to the working directory) and split into one part per
// material group of the file (mesh_materials maps the file's material names).
#pragma once
#include <string>
#include <vector>

#include "universe/shapes.hpp"

namespace eoir::universe {

constexpr int max_composite_depth = 8;
constexpr std::size_t max_composite_parts = 256;

// Parses and flattens (nested transforms composed). Throws eoir::Error
// (out_of_range, unknown_name, limit_exceeded) naming the JSON path under
// `field`, e.g. "composite[1].parts[0].dimensions_m[2]: must be > 0".
std::vector<ShapePart> parse_composite(const std::string& json_text, const std::string& field);

// A mesh's material map, {"<file material>": {"material", "temperature_K",
// "reflectance"}}, as JSON text (the object property mesh_materials).
MeshMaterials parse_mesh_materials(const std::string& json_text, const std::string& field);

}  // namespace eoir::universe
