// Where the engine's data folder is (data/README.md): the solar spectrum,
// materials, Earth rasters, star catalogue. In order: the folder the host
// asks for, $EOIR_DATA_DIR, share/eoir/data beside the installed library,
// and the build tree's data folder.
#pragma once
#include <string>

namespace eoir {

// `requested` may be empty. Returns a folder that exists, or the build tree's
// path if none does (loaders then fail naming the file they miss).
std::string resolve_data_dir(const std::string& requested);

}  // namespace eoir
