#pragma once
// A plain thread pool: `workers` threads (the calling one among them) take the items
// 0..count-1 in order, one at a time, so long and short items balance themselves. The batch
// runs its jobs on it, and a run alone its own work (util/run_threads.h).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace camcov {

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
  for (std::size_t w = 1; w < threadCount; ++w)
    threads.emplace_back(work);
  work();
  for (auto& t : threads)
    t.join();
}

}  // namespace camcov
