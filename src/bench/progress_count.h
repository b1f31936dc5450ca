#pragma once
// The progress line of a stretch of items, as every front end shows it: "[done/total] elapsed
// m:ss, ETA m:ss | what", the ETA from the rate of the items done in this sitting.
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace camcov::bench {

class ProgressCount {
 public:
  ProgressCount(std::size_t total, std::size_t alreadyDone);
  // Counts one more item done and returns its line; `what` is made printable. Thread-safe.
  std::string finished(const std::string& what);

 private:
  std::mutex mutex_;
  std::size_t total_;
  std::size_t done_;
  std::size_t doneAtStart_;
  std::chrono::steady_clock::time_point start_;
};

// "m:ss", or "h:mm:ss" from an hour on.
std::string formatDuration(double seconds);

}  // namespace camcov::bench
