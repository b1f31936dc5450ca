#pragma once
// How many threads one run may use for its own work: `camcov run --threads N` (by default every
// core it may run on). A batch runs its jobs one per thread and gives each run the threads left
// over, 1 when it has as many jobs as workers. Results
// never depend on it: the work split over threads is made of pure functions of their inputs
// (each thread has its own workspaces), taken up again in a fixed order.
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <thread>

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

// The cores this process may run on: its CPU affinity (`taskset -c 0` leaves one), else the
// machine's; at least 1. What `camcov run` and `camcov bench` use unless told otherwise.
inline unsigned availableCores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof set, &set) == 0) {
    return static_cast<unsigned>(std::max(1, CPU_COUNT(&set)));
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace camcov
