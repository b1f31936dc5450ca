#pragma once
// What a bench writes after its runs, one item at a time (videos, explorer pages, offline
// optima): how many were written, already up to date, or not written. An item that cannot be
// made is said (a warning to the observer) and skipped: the runs are the results, these only show
// or measure them.
#include <cstddef>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace camcov::bench {

class BenchObserver;

struct OutputBatch {
  std::size_t written = 0;
  std::size_t upToDate = 0;  // already there, made from the same inputs
  std::size_t failed = 0;    // each one explained in a warning

  // "wrote 3 videos in out/videos (1 up to date, 1 not written)", from "video" and "videos".
  std::string describe(std::string_view one, std::string_view many, const std::string& dir) const;
};

// The items that could not be made, collected from any thread, then said at once (after a
// progress line that would overwrite them).
class OutputProblems {
 public:
  void add(std::string problem);
  // Says each as a warning; returns how many there were.
  std::size_t report(BenchObserver& observer) const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> problems_;
};

}  // namespace camcov::bench
