#include "core/scratch_file.hpp"

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"

namespace eoir {
namespace {
std::string folder() {
  const char* dir = std::getenv("TMPDIR");
  return dir && *dir ? dir : "/tmp";
}
}  // namespace

ScratchFile::ScratchFile(std::uint64_t bytes, const std::string& what) : what_(what) {
  const std::string dir = folder();
  fd_ = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd_ < 0) {  // a file system without O_TMPFILE: a named file, unlinked at once
    std::string path = dir + "/eoir-scratch-XXXXXX";
    fd_ = ::mkstemp(path.data());
    if (fd_ >= 0) ::unlink(path.c_str());
  }
  if (fd_ < 0)
    throw Error(Status::io, what_ + ": cannot make a temporary file in " + dir + " (TMPDIR): " + std::strerror(errno));
  struct statvfs fs {};
  if (::fstatvfs(fd_, &fs) == 0) {
    const std::uint64_t free_bytes = static_cast<std::uint64_t>(fs.f_bavail) * fs.f_frsize;
    if (free_bytes < bytes) {
      ::close(fd_);
      throw Error(Status::io, what_ + ": needs " + std::to_string(bytes >> 20) + " MiB of temporary space in " + dir +
                                  " (TMPDIR), " + std::to_string(free_bytes >> 20) + " MiB free");
    }
  }
}

ScratchFile::~ScratchFile() {
  if (fd_ >= 0) ::close(fd_);
}

void ScratchFile::write(std::uint64_t offset, const void* data, std::size_t bytes) const {
  const char* p = static_cast<const char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::pwrite(fd_, p, bytes, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(Status::io, what_ + ": cannot write the temporary file: " + std::strerror(errno));
    p += n;
    offset += static_cast<std::uint64_t>(n);
    bytes -= static_cast<std::size_t>(n);
  }
}

void ScratchFile::read(std::uint64_t offset, void* data, std::size_t bytes) const {
  char* p = static_cast<char*>(data);
  while (bytes > 0) {
    const ssize_t n = ::pread(fd_, p, bytes, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw Error(Status::io, what_ + ": cannot read the temporary file" + (n == 0 ? std::string(": short") : ": " + std::string(std::strerror(errno))));
    p += n;
    offset += static_cast<std::uint64_t>(n);
    bytes -= static_cast<std::size_t>(n);
  }
}

}  // namespace eoir
