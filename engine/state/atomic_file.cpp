#include "state/atomic_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include "core/error.hpp"
#include "core/read_file.hpp"

namespace eoir::state {
namespace {
[[noreturn]] void fail(const std::string& what, const std::string& path, int err) {
  throw Error(Status::io, "path: cannot " + what + " '" + path + "': " + std::strerror(err));
}

std::string dir_of(const std::string& p) {
  const auto slash = p.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : p.substr(0, slash);
}

std::string base_of(const std::string& p) {
  const auto slash = p.find_last_of('/');
  return slash == std::string::npos ? p : p.substr(slash + 1);
}

// Follows symbolic links of the last component (a dangling link's target is
// created): the file that a plain open() for writing would write.
std::string resolve_links(const std::string& path) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::string target(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 4096) + 1, '\0');
    const ssize_t n = ::readlink(p.c_str(), target.data(), target.size());
    if (n < 0) fail("read the symbolic link", p, errno);
    target.resize(static_cast<std::size_t>(n));
    p = (!target.empty() && target[0] == '/') ? target : dir_of(p) + "/" + target;
  }
  fail("resolve", path, ELOOP);
}

std::string random_suffix() {
  static const char chars[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  thread_local std::mt19937_64 rng{std::random_device{}() ^ (static_cast<std::uint64_t>(::getpid()) << 32)};
  std::string s(6, 'x');
  for (char& c : s) c = chars[rng() % (sizeof chars - 1)];
  return s;
}

// Removes "<base>.tmp.XXXXXX" files beside the target that no writer holds
// (a writer keeps an exclusive flock on its temporary file until the rename;
// the lock dies with the process).
void remove_stale_temporaries(const std::string& dir, const std::string& base) {
  DIR* d = ::opendir(dir.c_str());
  if (d == nullptr) return;
  const std::string prefix = base + ".tmp.";
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name.size() != prefix.size() + 6 || name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string p = dir + "/" + name;
    const int fd = ::open(p.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) continue;
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && ::flock(fd, LOCK_EX | LOCK_NB) == 0) {
      struct stat now {};
      // Still the same file under that name: unlink it while holding the lock.
      if (::lstat(p.c_str(), &now) == 0 && now.st_ino == st.st_ino && now.st_dev == st.st_dev) ::unlink(p.c_str());
    }
    ::close(fd);
  }
  ::closedir(d);
}
}  // namespace

void write_file_atomically(const std::string& path, const std::string& contents) {
  const std::string target = resolve_links(path);
  const std::string dir = dir_of(target), base = base_of(target);
  struct stat existing {};
  const bool exists = ::stat(target.c_str(), &existing) == 0;
  // A device or FIFO at the target is not replaced by a file.
  if (exists) require_regular_file(target, existing.st_mode);
  remove_stale_temporaries(dir, base);

  // An unnamed file in the target's directory, or a named one if the file
  // system has no O_TMPFILE. New files get 0666 less the umask, as open() gives.
  std::string tmp;
  bool unnamed = true;
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd < 0) {
    unnamed = false;
    for (int tries = 0; fd < 0 && tries < 100; ++tries) {
      tmp = dir + "/" + base + ".tmp." + random_suffix();
      fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0) fail("create a temporary file beside", target, errno);
  }
  const auto give_up = [&](const std::string& what, const std::string& where, int err) {
    ::close(fd);
    if (!tmp.empty()) ::unlink(tmp.c_str());
    fail(what, where, err);
  };
  if (::flock(fd, LOCK_EX) != 0) give_up("lock a temporary file beside", target, errno);
  size_t written = 0;
  while (written < contents.size()) {
    const ssize_t n = ::write(fd, contents.data() + written, contents.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      give_up("write a temporary file beside", target, errno);
    }
    written += static_cast<size_t>(n);
  }
  if (exists && ::fchmod(fd, existing.st_mode & 07777) != 0) give_up("set the mode of a temporary file beside", target, errno);
  if (::fsync(fd) != 0) give_up("flush a temporary file beside", target, errno);
  if (unnamed) {
    const std::string proc = "/proc/self/fd/" + std::to_string(fd);
    for (int tries = 0; tries < 100; ++tries) {
      tmp = dir + "/" + base + ".tmp." + random_suffix();
      if (::linkat(AT_FDCWD, proc.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) == 0) break;
      const int err = errno;
      tmp.clear();
      if (err != EEXIST) give_up("name a temporary file beside", target, err);
    }
    if (tmp.empty()) give_up("name a temporary file beside", target, EEXIST);
  }
  if (std::rename(tmp.c_str(), target.c_str()) != 0) give_up("rename a temporary file onto", target, errno);
  tmp.clear();
  ::close(fd);  // releases the lock
  // Make the rename itself durable.
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    (void)::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace eoir::state
