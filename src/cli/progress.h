#pragma once
// Progress of a batch on stderr: on a terminal one live line (done/total, elapsed, ETA, the
// last finished job), in a log one plain line per finished job.
#include <chrono>
#include <mutex>
#include <string>

namespace camcov::cli {

class Progress {
 public:
  Progress(std::size_t total, std::size_t alreadyDone);
  // Thread-safe.
  void finished(const std::string& what);
  void close();

 private:
  std::mutex mutex_;
  std::size_t total_;
  std::size_t done_;
  std::size_t doneAtStart_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_;
};

std::string formatDuration(double seconds);

}  // namespace camcov::cli
