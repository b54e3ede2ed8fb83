#include "atmosphere/data_table.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.hpp"
#include "core/read_file.hpp"

namespace eoir::atmosphere {

DataTable read_data_table(const std::string& path) {
  const std::string text = read_file(path, std::size_t{8} << 20, "atmosphere tables");
  std::istringstream in(text);
  DataTable t;
  t.path = path;
  std::string l;
  for (std::size_t n = 1; std::getline(in, l); ++n) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    if (l.empty() || l[0] == '#') continue;
    std::vector<std::string> cells;
    std::istringstream cs(l);
    for (std::string c; std::getline(cs, c, ',');) cells.push_back(c);
    if (l.back() == ',') cells.emplace_back();
    if (t.header.empty()) {
      t.header = cells;
      continue;
    }
    std::vector<double> row(t.header.size(), std::nan(""));
    for (std::size_t i = 0; i < cells.size() && i < row.size(); ++i) {
      char* end = nullptr;
      const double x = std::strtod(cells[i].c_str(), &end);
      if (end != cells[i].c_str() && *end == '\0' && std::isfinite(x)) row[i] = x;
    }
    t.key.push_back(cells.empty() ? std::string() : cells[0]);
    t.rows.push_back(std::move(row));
    t.line.push_back(n);
  }
  if (t.rows.empty()) throw Error(Status::corrupt_file, path + ": no rows");
  return t;
}

std::size_t DataTable::column(const std::string& name, bool empty_ok) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) {
      for (std::size_t r = 0; r < rows.size() && !empty_ok; ++r)
        if (std::isnan(rows[r][i]))
          throw Error(Status::corrupt_file, path + ":" + std::to_string(line[r]) + ": " + name + ": not a number");
      return i;
    }
  throw Error(Status::corrupt_file, path + ": no column '" + name + "'");
}

}  // namespace eoir::atmosphere
