// What an engine reads from its data folder (data/README.md) and what the
// user adds to it: materials (spec 4.1.4.1, Appendix A) and the table of
// tabulated spectral radiances (4.1.4, the Sun first). Loaded once, when a
// world first needs it; shared read-only by every world built from it.
#pragma once
#include <string>

#include "universe/material.hpp"
#include "universe/spectrum_table.hpp"

namespace eoir::universe {

struct Library {
  std::string data_dir;
  MaterialLibrary materials;
  SpectrumTable spectra;
  // Reads data_dir/materials/*.json and data_dir/solar/e490.txt (throws io
  // or corrupt_file naming the file).
  static Library load(const std::string& data_dir);
};

}  // namespace eoir::universe
