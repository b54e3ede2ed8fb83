// Absorption by the atmosphere's gases along a path (spec 4.3.1.1; issue 20
// item 3): the band models of LOWTRAN 7 (Pierluissi and Maragoudakis 1986,
// AFGL-TR-86-0272; Kneizys et al. 1988) per absorber on their 5 cm^-1 grid,
// the water-vapour continuum, and ozone's UV and visible bands, from the
// tables of data/atmosphere/ (data/atmosphere/README.md).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "atmosphere/shell_path.hpp"

namespace eoir::atmosphere {

class MolecularAbsorption {
 public:
  // Reads the data folder's tables (throws io or corrupt_file naming the
  // file and line).
  static std::unique_ptr<const MolecularAbsorption> load(const std::string& data_dir);
  virtual ~MolecularAbsorption() = default;
  // -ln of the gases' transmittance at each wavelength (um) along a path
  // whose segments were kept (path_between(..., true)).
  virtual void optical_depths(const PathColumns& path, const std::vector<double>& wavelength_um,
                              std::vector<double>& tau) const = 0;
};

}  // namespace eoir::atmosphere
