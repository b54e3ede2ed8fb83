#include "core/mapped_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.hpp"
#include "core/read_file.hpp"

namespace eoir {

std::shared_ptr<const MappedFile> MappedFile::open(const std::string& path, std::size_t max_bytes,
                                                   const std::string& kind) {
  // As read_file: devices and FIFOs are refused before they are opened.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) require_regular_file(path, st.st_mode);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) throw Error(Status::io, "path: cannot open '" + path + "': " + std::strerror(errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  if (::fstat(fd, &st) != 0) throw Error(Status::io, "path: cannot read '" + path + "': " + std::strerror(errno));
  require_regular_file(path, st.st_mode);
  if (static_cast<unsigned long long>(st.st_size) > max_bytes)
    throw Error(Status::corrupt_file, "file: '" + path + "' is larger than " + std::to_string(max_bytes >> 20) +
                                          " MiB, the limit of " + kind);
  if (st.st_size == 0) throw Error(Status::corrupt_file, "file: '" + path + "' is empty");
  const auto size = static_cast<std::size_t>(st.st_size);
  void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  if (p == MAP_FAILED) throw Error(Status::io, "path: cannot map '" + path + "': " + std::strerror(errno));
  return std::shared_ptr<const MappedFile>(new MappedFile(static_cast<const char*>(p), size, path));
}

MappedFile::~MappedFile() { ::munmap(const_cast<char*>(data_), size_); }

}  // namespace eoir
