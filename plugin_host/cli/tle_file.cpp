#include "tle_file.hpp"

#include <set>
#include <stdexcept>

namespace eoir::cli {
namespace {

std::string trim_right(std::string s) {
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.pop_back();
  return s;
}

}  // namespace

std::vector<TleSet> parse_tle_file(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t start = 0; start <= text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  std::vector<TleSet> sets;
  std::set<std::string> names;
  std::size_t i = 0;
  const auto at = [](std::size_t index) { return "line " + std::to_string(index + 1) + ": "; };
  while (i < lines.size()) {
    if (trim_right(lines[i]).empty()) {
      ++i;
      continue;
    }
    const std::size_t title = i;
    std::string name = trim_right(lines[i]);
    if (name.rfind("0 ", 0) == 0) name = trim_right(name.substr(2));
    if (name.rfind("1 ", 0) == 0 && name.size() >= 60)
      throw std::invalid_argument(at(title) + "a title line (the satellite's name) must come before line 1");
    if (name.empty() || name.size() > 63)
      throw std::invalid_argument(at(title) + "the title (the satellite's name) must be 1 to 63 bytes");
    if (title + 2 >= lines.size() || trim_right(lines[title + 1]).empty() || trim_right(lines[title + 2]).empty())
      throw std::invalid_argument(at(title) + "the set '" + name + "' is cut short: a title, line 1 and line 2");
    try {
      sets.push_back(TleSet{name, title + 1, Sgp4::from_tle(lines[title + 1], lines[title + 2])});
    } catch (const std::invalid_argument& e) {
      const std::string why = e.what();
      throw std::invalid_argument(at(why.rfind("line 1", 0) == 0 ? title + 1 : title + 2) + "'" + name + "': " + why);
    }
    if (!names.insert(name).second)
      throw std::invalid_argument(at(title) + "a satellite named '" + name + "' is listed twice");
    i = title + 3;
  }
  if (sets.empty()) throw std::invalid_argument("line 1: no two-line element sets in the file");
  return sets;
}

}  // namespace eoir::cli
