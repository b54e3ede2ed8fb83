#include "core/read_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/error.hpp"

namespace eoir {
namespace {
// Closes the descriptor on every way out.
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
  throw Error(Status::io, "path: cannot " + what + " '" + path + "': " + std::strerror(err));
}
}  // namespace

void require_regular_file(const std::string& path, unsigned mode) {
  if (S_ISREG(mode)) return;
  const char* what = S_ISDIR(mode)    ? "a directory"
                     : S_ISFIFO(mode) ? "a FIFO"
                     : S_ISCHR(mode)  ? "a character device"
                     : S_ISBLK(mode)  ? "a block device"
                     : S_ISSOCK(mode) ? "a socket"
                                      : "a special file";
  throw Error(Status::io, "path: '" + path + "' is not a regular file (" + what + ")");
}

std::string read_file(const std::string& path, std::size_t max_bytes, const std::string& kind) {
  // Devices and FIFOs are refused before they are opened (opening one may
  // block or act); O_NONBLOCK and fstat cover a file replaced in between.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) require_regular_file(path, st.st_mode);
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK)};
  if (file.fd < 0) fail("open", path, errno);
  if (::fstat(file.fd, &st) != 0) fail("read", path, errno);
  require_regular_file(path, st.st_mode);
  const auto too_large = [&] {
    throw Error(Status::corrupt_file, "file: '" + path + "' is larger than " + std::to_string(max_bytes >> 20) +
                                          " MiB, the limit of " + kind);
  };
  if (static_cast<unsigned long long>(st.st_size) > max_bytes) too_large();
  // Read in place into storage of the file's size (one allocation, no
  // copies: the 6 MB star catalogue loads in milliseconds); a file that grows
  // meanwhile is read up to the cap.
  std::string out(static_cast<std::size_t>(st.st_size) + 1, '\0');
  std::size_t size = 0;
  for (;;) {
    if (size == out.size()) {
      if (size > max_bytes) too_large();
      out.resize(std::min(2 * size, max_bytes + 1));
    }
    const ssize_t n = ::read(file.fd, &out[size], out.size() - size);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("read", path, errno);
    }
    if (n == 0) break;
    size += static_cast<std::size_t>(n);
    if (size > max_bytes) too_large();
  }
  out.resize(size);
  return out;
}

}  // namespace eoir
