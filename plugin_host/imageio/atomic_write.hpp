// Atomic whole-file write for the image writers: the bytes go to a unique
// temporary file beside the target (same directory, so same file system),
// which is flushed with fsync and then renamed over the target; the
// directory is fsync'ed afterwards. On any error the temporary file is
// removed and the previous target (if any) is left untouched.
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace eoir::imageio {

class ImageIoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws ImageIoError naming the path and the system error.
void write_file_atomically(const std::string& path, const void* data, std::size_t size);

}  // namespace eoir::imageio
