#include "universe/predefined_composites.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.hpp"

namespace eoir::universe {

void PredefinedComposites::load_directory(const std::string& dir) {
  constexpr std::uintmax_t max_bytes = 16u << 20;
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) return;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (entry.path().extension() != ".json") continue;
    const std::string path = entry.path().string();
    if (entry.file_size(ec) > max_bytes) throw Error(Status::corrupt_file, path + ": larger than 16 MiB");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(Status::io, "satellites: cannot read '" + path + "'");
    std::ostringstream text;
    text << in.rdbuf();
    nlohmann::json doc;
    try {
      doc = nlohmann::json::parse(text.str());
    } catch (const nlohmann::json::exception& e) {
      throw Error(Status::corrupt_file, path + ": not valid JSON: " + e.what());
    }
    if (!doc.is_object() || doc.value("format", "") != "eoir-composite" || !doc.contains("name") ||
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
