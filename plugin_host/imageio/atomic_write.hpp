// Atomic whole-file write for the image writers: the bytes go to a unique
// temporary file beside the target (same directory, so same file system),
// which is flushed with fsync and then renamed over the target; the
// directory is fsync'ed afterwards. On any error the temporary file is
// removed and the previous target (if any) is left untouched.
//
// As the engine's state files (engine/state/atomic_file.hpp): only a
// regular file is replaced (a device, FIFO or directory is refused), an
// existing target keeps its permission bits (new files get 0666 less the umask), a
// symbolic link is written through to its target (the link stays), and
// temporary files "<target>.tmp.<pid>.<n>" left by a writer that died (no
// process <pid>) are removed by the next write of that target.
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

// The same replacement for a file written piece by piece (e.g. a FITS file
// streamed through cfitsio): the constructor resolves links, refuses a
// non-regular target, removes stale temporaries and names a unique
// temporary beside the target (not yet created: the caller creates it,
// exclusively); commit() gives it the target's permission bits, fsyncs it,
// renames it over the target and fsyncs the directory (commit(fd) uses and
// closes the caller's open descriptor of the temporary; without one, the
// temporary, already closed, is opened again). Until commit()
// succeeds the target is untouched, and the destructor (or a failed
// commit) removes the temporary. Throws ImageIoError.
class AtomicReplacement {
 public:
  explicit AtomicReplacement(const std::string& path);
  ~AtomicReplacement();
  AtomicReplacement(const AtomicReplacement&) = delete;
  AtomicReplacement& operator=(const AtomicReplacement&) = delete;

  const std::string& target() const { return target_; }
  const std::string& temporary() const { return temporary_; }
  void commit(int fd = -1);

 private:
  std::string target_, temporary_;
  bool target_exists_ = false;
  unsigned target_mode_ = 0;
  bool committed_ = false;
};

}  // namespace eoir::imageio
