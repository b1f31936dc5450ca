// util/worker_pool.h: the items run once each, and a job's CPU time counts the threads it started.
#include "util/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

namespace camcov {
namespace {

// Keeps the calling thread busy until it has used `seconds` of CPU.
void spin(double seconds) {
  const double until = threadCpuSeconds() + seconds;
  while (threadCpuSeconds() < until) {
  }
}

TEST(WorkerPool, EveryItemRunsOnceOnAnyNumberOfWorkers) {
  for (const unsigned workers : {0u, 1u, 3u, 16u}) {
    std::vector<std::atomic<int>> runs(10);
    forEachOnWorkers(runs.size(), workers, [&](std::size_t i) { ++runs[i]; });
    for (const auto& r : runs)
      EXPECT_EQ(r.load(), 1) << workers << " workers";
  }
}

TEST(WorkerPool, ACallersCpuTimeCountsTheThreadsItStartedAndTheirs) {
  // Four items of 20 ms of CPU each on two threads, each item starting two threads of its own
  // for two halves: 80 ms of CPU in all, whichever thread ran what.
  const double start = cpuSecondsWithJoinedThreads();
  forEachOnWorkers(4, 2,
                   [](std::size_t) { forEachOnWorkers(2, 2, [](std::size_t) { spin(0.010); }); });
  EXPECT_GE(cpuSecondsWithJoinedThreads() - start, 0.080);
}

}  // namespace
}  // namespace camcov
