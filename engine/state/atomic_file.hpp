// Atomic writes: write a temporary file beside the target, flush it to disk,
// then rename over the target. A crash or error at
// any point leaves the old file intact (house rule 5).
//
// Writes keep what the user set up: only a regular file is replaced (a
// device such as /dev/null, a FIFO or a directory at the target is refused:
// Error(io) naming it), a symbolic link is written through (its target is
// replaced, the link stays), an existing file keeps its permission
// bits (a 0600 file stays private; a new file gets 0666 less the umask), and
// the directory is flushed after the rename. The data are written to an
// unnamed file (O_TMPFILE) that gets the name "<target>.tmp.XXXXXX" only for
// the rename; a save killed in that instant, or on a file system without
// O_TMPFILE, leaves such a file, and the next save of that target removes
// every one of them that no live writer holds (writers hold an flock on
// their temporary file).
#pragma once
#include <cstddef>
#include <string>

namespace eoir::state {

// Throws eoir::Error(io) naming the path and the system error.
void write_file_atomically(const std::string& path, const std::string& contents);

}  // namespace eoir::state
