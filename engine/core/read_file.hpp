// Whole-file reads of input files with a size cap: a regular file larger
// than the cap is refused before it is read, and pipes and devices
// (/dev/zero) are read only up to the cap, so no input can grow memory
// without bound.
#pragma once
#include <cstddef>
#include <string>

namespace eoir {

// The contents of `path`, at most max_bytes. Throws eoir::Error(io) naming
// the path and the system error if it cannot be opened or read (or is a
// directory), Error(corrupt_file) "file: 'PATH' is larger than N MiB, the
// limit of KIND" if it is larger.
std::string read_file(const std::string& path, std::size_t max_bytes, const std::string& kind);

}  // namespace eoir
