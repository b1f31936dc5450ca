#include "bench/progress_count.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "util/printable.h"

namespace camcov::bench {

std::string formatDuration(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  return s >= 3600 ? fmt::format("{}:{:02}:{:02}", s / 3600, s / 60 % 60, s % 60)
                   : fmt::format("{}:{:02}", s / 60, s % 60);
}

ProgressCount::ProgressCount(std::size_t total, std::size_t alreadyDone)
    : total_(total),
      done_(alreadyDone),
      doneAtStart_(alreadyDone),
      start_(std::chrono::steady_clock::now()) {}

std::string ProgressCount::finished(const std::string& what) {
  const std::lock_guard lock(mutex_);
  ++done_;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = static_cast<double>(done_ - doneAtStart_) / std::max(elapsed, 1e-9);
  const double eta = static_cast<double>(total_ - done_) / std::max(rate, 1e-9);
  // `what` names a scene or quotes a failed job's message: text from files, made printable.
  return fmt::format("[{}/{}] {} elapsed, ETA {} | {}", done_, total_, formatDuration(elapsed),
                     formatDuration(eta), printable(what));
}

}  // namespace camcov::bench
