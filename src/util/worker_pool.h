#pragma once
// A plain thread pool: `workers` threads (the calling one among them) take the items
// 0..count-1 in order, one at a time, so long and short items balance themselves. The batch
// runs its jobs on it, and a run its own work (util/run_threads.h).
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <mutex>
#include <thread>
#include <vector>

namespace camcov {

// CPU seconds the calling thread has used.
inline double threadCpuSeconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
// CPU seconds of the threads forEachOnWorkers started for the calling thread, counted as each
// was joined, theirs included: with threadCpuSeconds(), what a job cost on however many threads.
inline double& joinedThreadsCpuSeconds() {
  thread_local double seconds = 0.0;
  return seconds;
}
inline double cpuSecondsWithJoinedThreads() {
  return threadCpuSeconds() + joinedThreadsCpuSeconds();
}

// `task(i)` is called once per item, from any of the threads; it must not throw.
template <class Task>
void forEachOnWorkers(std::size_t count, unsigned workers, const Task& task) {
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < count; i = next++)
      task(i);
  };
  // No more threads than items; the calling thread is one of them.
  const std::size_t threadCount = std::min<std::size_t>(std::max(workers, 1u), count);
  std::vector<std::thread> threads;
  std::mutex mutex;
  double joined = 0.0;  // the started threads' CPU seconds
  for (std::size_t w = 1; w < threadCount; ++w) {
    threads.emplace_back([&] {
      work();
      const double mine = cpuSecondsWithJoinedThreads();
      const std::lock_guard lock(mutex);
      joined += mine;
    });
  }
  work();
  for (auto& t : threads)
    t.join();
  joinedThreadsCpuSeconds() += joined;
}

}  // namespace camcov
