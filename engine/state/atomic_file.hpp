// Whole-file reads and atomic writes: write a temporary file beside the
// target, flush it to disk, then rename over the target. A crash or error at
// any point leaves the old file intact (house rule 5).
#pragma once
#include <string>

namespace eoir::state {

// Throws eoir::Error(io) naming the path and the system error.
void write_file_atomically(const std::string& path, const std::string& contents);
std::string read_file(const std::string& path);

}  // namespace eoir::state
