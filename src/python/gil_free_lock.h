#pragma once
// Locks that native objects shared by Python threads take around their state. Each is waited
// for without the GIL, so the thread holding it can always take the GIL back: two threads
// using one object take turns instead of racing, and never deadlock on the GIL.
#include <pybind11/pybind11.h>

#include <algorithm>
#include <mutex>
#include <vector>

namespace camcov::python {

// Returns with the GIL held again and `mutex` held until the lock goes.
inline std::unique_lock<std::mutex> lockWithoutGil(std::mutex& mutex) {
  const pybind11::gil_scoped_release free;
  return std::unique_lock(mutex);
}

// Every mutex of `mutexes`, each once however often it appears, taken in address order: two
// threads locking overlapping sets never wait for each other in a cycle.
inline std::vector<std::unique_lock<std::mutex>> lockAllWithoutGil(
    std::vector<std::mutex*> mutexes) {
  std::sort(mutexes.begin(), mutexes.end());
  mutexes.erase(std::unique(mutexes.begin(), mutexes.end()), mutexes.end());
  std::vector<std::unique_lock<std::mutex>> locks;
  locks.reserve(mutexes.size());
  const pybind11::gil_scoped_release free;
  for (std::mutex* mutex : mutexes)
    locks.emplace_back(*mutex);
  return locks;
}

}  // namespace camcov::python
