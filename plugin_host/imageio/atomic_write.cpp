#include "atomic_write.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace eoir::imageio {

namespace {
std::string errno_text(int err) { return std::string(std::strerror(err)); }

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

// The file a plain open() for writing would write: symbolic links of the
// last component followed (a dangling link's target is created).
std::string resolve_links(const std::string& path) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::string target(4096, '\0');
    const ssize_t n = ::readlink(p.c_str(), target.data(), target.size() - 1);
    if (n < 0) throw ImageIoError("cannot read the symbolic link " + p + ": " + errno_text(errno));
    target.resize(static_cast<std::size_t>(n));
    p = (!target.empty() && target[0] == '/') ? target : directory_of(p) + "/" + target;
  }
  throw ImageIoError("too many symbolic links: " + path);
}

// Removes "<base>.tmp.<pid>.<n>" beside the target when process <pid> is gone.
void remove_stale_temporaries(const std::string& target) {
  const std::string dir = directory_of(target);
  const std::string base = target.substr(target.find_last_of('/') == std::string::npos ? 0 : target.find_last_of('/') + 1);
  const std::string prefix = base + ".tmp.";
  DIR* d = ::opendir(dir.c_str());
  if (d == nullptr) return;
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    const auto dot = rest.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == rest.size()) continue;
    if (rest.find_first_not_of("0123456789.") != std::string::npos) continue;
    const long pid = std::strtol(rest.substr(0, dot).c_str(), nullptr, 10);
    if (pid <= 0 || pid == static_cast<long>(::getpid())) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive (or not ours to judge)
    ::unlink((dir + "/" + name).c_str());
  }
  ::closedir(d);
}
}  // namespace

AtomicReplacement::AtomicReplacement(const std::string& path_in) {
  static std::atomic<unsigned> counter{0};
  if (path_in.empty()) throw ImageIoError("image output path is empty");
  target_ = resolve_links(path_in);
  struct stat existing {};
  target_exists_ = ::stat(target_.c_str(), &existing) == 0;
  // A device or FIFO at the target is not replaced by a file.
  if (target_exists_ && !S_ISREG(existing.st_mode))
    throw ImageIoError("cannot replace " + target_ + ": not a regular file (" +
                       (S_ISDIR(existing.st_mode)    ? "a directory"
                        : S_ISFIFO(existing.st_mode) ? "a FIFO"
                        : S_ISCHR(existing.st_mode)  ? "a character device"
                        : S_ISBLK(existing.st_mode)  ? "a block device"
                        : S_ISSOCK(existing.st_mode) ? "a socket"
                                                     : "a special file") +
                       ")");
  target_mode_ = static_cast<unsigned>(existing.st_mode & 07777);
  remove_stale_temporaries(target_);
  // Unique per process and object; the creator opens it exclusively.
  temporary_ = target_ + ".tmp." + std::to_string(static_cast<long>(::getpid())) + "." +
               std::to_string(counter.fetch_add(1));
}

AtomicReplacement::~AtomicReplacement() {
  if (!committed_) ::unlink(temporary_.c_str());
}

void AtomicReplacement::commit(int fd) {
  if (committed_) {
    if (fd >= 0) ::close(fd);
    throw ImageIoError("file " + target_ + " is already in place");
  }
  // The writer's descriptor, or the temporary opened again (read-only, or
  // write-only when the umask left the owner no read permission).
  if (fd < 0) fd = ::open(temporary_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fd = ::open(temporary_.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) throw ImageIoError("cannot open " + temporary_ + ": " + errno_text(errno));
  const auto fail = [&](const std::string& what) {
    const int err = errno;
    ::close(fd);
    throw ImageIoError(what + " " + temporary_ + ": " + errno_text(err));
  };
  if (target_exists_ && ::fchmod(fd, static_cast<mode_t>(target_mode_)) != 0) fail("cannot set the mode of");
  if (::fsync(fd) != 0) fail("cannot fsync");
  if (::close(fd) != 0) throw ImageIoError("cannot close " + temporary_ + ": " + errno_text(errno));
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0)
    throw ImageIoError("cannot rename " + temporary_ + " to " + target_ + ": " + errno_text(errno));
  committed_ = true;
  // Make the rename itself durable (best effort: not all file systems allow
  // it).
  const int dfd = ::open(directory_of(target_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    (void)::fsync(dfd);
    ::close(dfd);
  }
}

void write_file_atomically(const std::string& path, const void* data, std::size_t size) {
  AtomicReplacement file(path);
  const std::string& tmp = file.temporary();
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) throw ImageIoError("cannot create " + tmp + ": " + errno_text(errno));
  const char* p = static_cast<const char*>(data);
  std::size_t left = size;
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      throw ImageIoError("cannot write " + tmp + ": " + errno_text(err));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  file.commit(fd);
}

}  // namespace eoir::imageio
