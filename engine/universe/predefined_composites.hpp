// The selectable composite satellites of spec 4.3.3 (LEO Earth observing,
// LEO communications, GEO communications): the data folder's satellites/
// files (data/satellites/README.md), by name. Setting the `composite`
// property to one of these names sets it to that file's parts.
#pragma once
#include <map>
#include <string>

namespace eoir::universe {

class PredefinedComposites {
 public:
  // Reads dir/*.json ("eoir-composite" files); throws io / corrupt_file
  // naming the file. A missing folder gives an empty set.
  void load_directory(const std::string& dir);
  // The parts array (JSON text) of the named satellite; throws unknown_name
  // naming `field` and the known names.
  const std::string& parts(const std::string& name, const std::string& field) const;
  // A value of the composite property that names a satellite rather than
  // giving parts (no '[' or '{').
  static bool is_name(const std::string& value);

 private:
  std::map<std::string, std::string> parts_;
};

}  // namespace eoir::universe
