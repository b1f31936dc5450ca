#include "cli/progress.h"

#include <unistd.h>

#include <cstdio>

namespace camcov::cli {

Progress::Progress(std::size_t total, std::size_t alreadyDone)
    : count_(total, alreadyDone), terminal_(::isatty(STDERR_FILENO) != 0) {}

void Progress::finished(const std::string& what) {
  const std::string text = count_.finished(what);
  // Written past std::cerr's filter (terminal_safe_stream.h) for the live line's own control
  // codes; the text itself is printable already.
  if (terminal_) {
    std::fprintf(stderr, "\r\033[K%s", text.c_str());
  } else {
    std::fprintf(stderr, "%s\n", text.c_str());
  }
  std::fflush(stderr);
}

void Progress::close() {
  if (terminal_) std::fprintf(stderr, "\n");
}

}  // namespace camcov::cli
