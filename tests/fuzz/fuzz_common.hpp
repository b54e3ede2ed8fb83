// Shared by the fuzz targets: a private temporary file per process (the C
// ABI loads state and sensor files by path) and the statuses a file may get.
#pragma once
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "eoir/eoir.h"

namespace eoir_fuzz {

inline const std::string& input_path() {
  static const std::string path = [] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir != nullptr && dir[0] != '\0' ? dir : "/tmp") + "/eoir_fuzz_input." +
           std::to_string(static_cast<long>(getpid()));
  }();
  return path;
}

// A single-threaded engine with a fixed seed, for the whole fuzzing process.
inline eoir_engine new_engine() {
  eoir_engine_desc d;
  std::memset(&d, 0, sizeof d);
  d.struct_size = sizeof d;
  d.threads = 1;
  d.seed = 1;
  eoir_engine e = nullptr;
  if (eoir_engine_create(&d, &e) != EOIR_OK) std::abort();
  return e;
}

inline const char* write_input(const unsigned char* data, std::size_t size) {
  FILE* f = std::fopen(input_path().c_str(), "wb");
  if (f == nullptr) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  return input_path().c_str();
}

// A file is loaded, or refused as corrupt, too new, unreadable or naming
// something unknown or out of range; EOIR_ERR_INTERNAL (a bug) or a status
// without a message is a finding.
inline void check_status(eoir_status s) {
  if (s == EOIR_OK) return;
  const bool expected = s == EOIR_ERR_CORRUPT_FILE || s == EOIR_ERR_FILE_VERSION || s == EOIR_ERR_IO ||
                        s == EOIR_ERR_UNKNOWN_NAME || s == EOIR_ERR_OUT_OF_RANGE || s == EOIR_ERR_LIMIT_EXCEEDED ||
                        s == EOIR_ERR_ALREADY_EXISTS || s == EOIR_ERR_NOT_ALLOWED || s == EOIR_ERR_TYPE_MISMATCH;
  if (!expected || eoir_last_error()[0] == '\0') {
    std::fprintf(stderr, "fuzz: unexpected %s: '%s'\n", eoir_status_name(s), eoir_last_error());
    std::abort();
  }
}

}  // namespace eoir_fuzz
