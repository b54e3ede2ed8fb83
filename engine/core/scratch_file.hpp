// An unnamed temporary file (O_TMPFILE in $TMPDIR, else /tmp) for data too
// large to hold in memory while a frame is made (sensor/scene_convolution.hpp):
// read and written at offsets, from any thread; gone when closed, even if
// the process dies.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace eoir {

class ScratchFile {
 public:
  // Throws Error(io) naming `what` and the folder if none can be made or
  // the folder has less than `bytes` free.
  ScratchFile(std::uint64_t bytes, const std::string& what);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  void write(std::uint64_t offset, const void* data, std::size_t bytes) const;
  void read(std::uint64_t offset, void* data, std::size_t bytes) const;

 private:
  int fd_ = -1;
  std::string what_;
};

}  // namespace eoir
