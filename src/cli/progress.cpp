#include "cli/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

#include "util/printable.h"

namespace camcov::cli {

std::string formatDuration(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
                   : fmt::format("{}:{:02}", s / 60, s % 60);
}

Progress::Progress(std::size_t total, std::size_t alreadyDone)
    : total_(total),
      done_(alreadyDone),
      doneAtStart_(alreadyDone),
      terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

void Progress::finished(const std::string& what) {
  const std::lock_guard lock(mutex_);
  ++done_;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = static_cast<double>(done_ - doneAtStart_) / std::max(elapsed, 1e-9);
  const double eta = static_cast<double>(total_ - done_) / std::max(rate, 1e-9);
  // Written past std::cerr's filter (terminal_safe_stream.h) for the live line's own control
  // codes, so `what` (a scene's name, a failed job's message) is made printable here.
  const std::string text =
      fmt::format("[{}/{}] {} elapsed, ETA {} | {}", done_, total_, formatDuration(elapsed),
                  formatDuration(eta), printable(what, {.keepLines = false}));
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
