#pragma once
// How many threads one run may use for its own work: `camcov run --threads N` when the run is
// alone on the machine. A batch runs its jobs one per thread and leaves this at 1. Results
// never depend on it: the work split over threads is made of pure functions of their inputs
// (each thread has its own workspaces), taken up again in a fixed order.
#include <algorithm>
#include <atomic>

namespace camcov {

inline std::atomic<unsigned>& runThreadsSetting() {
  static std::atomic<unsigned> threads{1};
  return threads;
}
inline unsigned runThreads() {
  return runThreadsSetting().load(std::memory_order_relaxed);
}
inline void setRunThreads(unsigned threads) {
  runThreadsSetting().store(std::max(threads, 1u), std::memory_order_relaxed);
}

}  // namespace camcov
