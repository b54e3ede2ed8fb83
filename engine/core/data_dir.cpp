#include "core/data_dir.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>

namespace eoir {
namespace {
namespace fs = std::filesystem;

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

// share/eoir/data relative to the shared object holding this code
// (<prefix>/lib[/multiarch]/libeoir.so -> <prefix>/share/eoir/data).
std::string installed_data_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&installed_data_dir), &info) == 0 || !info.dli_fname) return "";
  fs::path dir = fs::path(info.dli_fname).parent_path();
  for (int up = 0; up < 3 && !dir.empty(); ++up, dir = dir.parent_path())
    if (is_dir(dir / "share" / "eoir" / "data")) return (dir / "share" / "eoir" / "data").string();
  return "";
}
}  // namespace

std::string resolve_data_dir(const std::string& requested) {
  if (!requested.empty()) return requested;
  if (const char* env = std::getenv("EOIR_DATA_DIR"); env && *env) return env;
  if (std::string installed = installed_data_dir(); !installed.empty()) return installed;
  return EOIR_BUILD_DATA_DIR;
}

}  // namespace eoir
