// The tables of the data folder's atmosphere/ (data/atmosphere/README.md):
// `# ` comment lines, a header line of column names, then comma-separated
// rows. The first column is kept as text (a name or a number); every other
// cell is read as a number (NaN where it is empty or not a number).
#pragma once
#include <string>
#include <vector>

namespace eoir::atmosphere {

struct DataTable {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::string> key;           // each row's first cell
  std::vector<std::vector<double>> rows;  // one value per header column (the first NaN or its number)
  std::vector<std::size_t> line;          // each row's line in the file
  // The index of a column whose cells all hold numbers (empty_ok: or
  // nothing); throws corrupt_file naming the file, line and column.
  std::size_t column(const std::string& name, bool empty_ok = false) const;
};

// Reads a table of at most 8 MiB (throws io or corrupt_file naming the file).
DataTable read_data_table(const std::string& path);

}  // namespace eoir::atmosphere
