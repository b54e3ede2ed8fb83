// A regular file mapped read-only into memory (POSIX mmap): opening costs a
// few system calls, pages are read from the disk only when touched, and
// every mapping of the same file shares the page cache. For large read-only
// tables such as the star catalogue (universe/star_catalog.hpp).
#pragma once
#include <cstddef>
#include <memory>
#include <string>

namespace eoir {

class MappedFile {
 public:
  // Throws eoir::Error(io) naming the path if it cannot be opened or mapped,
  // as require_regular_file (core/read_file.hpp) if it is not a regular
  // file, Error(corrupt_file) if it is larger than max_bytes or empty.
  static std::shared_ptr<const MappedFile> open(const std::string& path, std::size_t max_bytes,
                                                const std::string& kind);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const char* data() const { return data_; }
  std::size_t size() const { return size_; }
  const std::string& path() const { return path_; }

 private:
  MappedFile(const char* data, std::size_t size, std::string path) : data_(data), size_(size), path_(std::move(path)) {}
  const char* data_;
  std::size_t size_;
  std::string path_;
};

}  // namespace eoir
