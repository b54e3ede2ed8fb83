// Whole-file reads of input files with a size cap: only regular files are
// read (a FIFO, which would block, a device such as /dev/zero, a socket or
// a directory is refused without reading or waiting), and a file larger
// than the cap is refused before it is read, so no input can hang the
// engine or grow its memory without bound.
#pragma once
#include <cstddef>
#include <string>

namespace eoir {

// The contents of `path`, at most max_bytes. Throws eoir::Error(io) naming
// the path and the system error if it cannot be opened or read, as
// require_regular_file if it is not a regular file, Error(corrupt_file)
// "file: 'PATH' is larger than N MiB, the limit of KIND" if it is larger.
std::string read_file(const std::string& path, std::size_t max_bytes, const std::string& kind);

// Throws eoir::Error(io) "path: 'PATH' is not a regular file (a FIFO)"
// unless `mode` (st_mode of stat) is a regular file's: the files the engine
// reads and the files its saves replace are regular files only.
void require_regular_file(const std::string& path, unsigned mode);

}  // namespace eoir
