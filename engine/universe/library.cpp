#include "universe/library.hpp"

#include <filesystem>

#include "core/error.hpp"

namespace eoir::universe {

Library Library::load(const std::string& data_dir) {
  Library lib;
  lib.data_dir = data_dir;
  lib.spectra = SpectrumTable::load(data_dir);
  const std::string materials = data_dir + "/materials";
  std::error_code ec;
  if (!std::filesystem::is_directory(materials, ec))
    throw Error(Status::io, "data: no materials folder '" + materials + "' (build the data folder: .ci/setup)");
  lib.materials.load_directory(materials);
  return lib;
}

}  // namespace eoir::universe
