#pragma once
// Stopping long work when the person who started it asks: a run checks between its steps and
// a batch before each job, so that Ctrl-C in Python ends camcov.run, simulate and bench within
// a step (the CLI needs none of it: SIGINT ends the process, what it wrote is whole and its
// temporary files are removed, cli/signal_cleanup.h). A caller that can be interrupted
// installs a check.
#include <atomic>
#include <stdexcept>

namespace camcov {

class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

// Returns true when the work must stop. Called from any thread of the work, once a step: it
// must be cheap, and safe to call concurrently.
using InterruptCheck = bool (*)();

namespace detail {
inline std::atomic<InterruptCheck>& installedInterruptCheck() {
  static std::atomic<InterruptCheck> check{nullptr};
  return check;
}
}  // namespace detail

// Installs `check` for the rest of the process (the Python module, when it is imported);
// nullptr: none, as in the CLI.
inline void installInterruptCheck(InterruptCheck check) {
  detail::installedInterruptCheck().store(check);
}

// Throws Interrupted if the installed check says the work must stop.
inline void throwIfInterrupted() {
  const InterruptCheck check = detail::installedInterruptCheck().load(std::memory_order_relaxed);
  if (check != nullptr && check()) throw Interrupted();
}

}  // namespace camcov
