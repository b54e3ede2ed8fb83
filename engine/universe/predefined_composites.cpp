#include "universe/predefined_composites.hpp"

#include <algorithm>
#include <filesystem>

#include "core/error.hpp"
#include "core/read_file.hpp"
#include "universe/json_document.hpp"

namespace eoir::universe {

void PredefinedComposites::load_directory(const std::string& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.path().extension() != ".json") continue;
    const std::string path = entry.path().string();
    const nlohmann::json doc = parse_json_document(read_file(path, 16u << 20, "a composite file"), path);
    if (!doc.is_object() || !doc.contains("format") || doc["format"] != "eoir-composite" || !doc.contains("name") ||
        !doc["name"].is_string() || !doc.contains("parts") || !doc["parts"].is_array())
      throw Error(Status::corrupt_file, path + ": not an eoir-composite file (format, name, parts)");
    parts_[doc["name"].get<std::string>()] = doc["parts"].dump();
  }
  if (ec) throw Error(Status::io, "satellites: cannot list '" + dir + "': " + ec.message());
}

const std::string& PredefinedComposites::parts(const std::string& name, const std::string& field) const {
  const auto it = parts_.find(name);
  if (it != parts_.end()) return it->second;
  std::string known;
  for (const auto& [n, p] : parts_) known += (known.empty() ? "" : ", ") + n;
  throw Error(Status::unknown_name,
              field + ": '" + name + "' is neither a parts array nor a predefined satellite (known: " + known + ")");
}

bool PredefinedComposites::is_name(const std::string& value) {
  return value.find_first_of("[{") == std::string::npos &&
         std::any_of(value.begin(), value.end(), [](char c) { return c != ' ' && c != '\t' && c != '\n'; });
}

}  // namespace eoir::universe
