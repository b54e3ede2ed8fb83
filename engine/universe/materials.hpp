// Surface materials (spec 4.3.3-4.3.5). Spectral reflectance tables arrive
// with the reflection issue; here a material is a name, and gray_body uses the
// object's `reflectance` property as its spectrally flat SRF.
#pragma once
#include <string>
#include <vector>

namespace eoir::universe {

const std::vector<const char*>& material_names();
// Throws eoir::Error(unknown_name) naming `field` and listing the materials.
void check_material(const std::string& name, const std::string& field);

}  // namespace eoir::universe
