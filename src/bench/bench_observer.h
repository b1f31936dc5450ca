#pragma once
// What a bench says while it works. The bench stage prints nothing: the command line shows
// these on its terminal (cli/terminal_observer.h), the Python module on sys.stdout and
// sys.stderr, a test keeps them. Lines carry no newline. Calls may come from worker threads;
// an observer locks what it shares.
#include <cstddef>
#include <string>

namespace camcov::bench {

class BenchObserver {
 public:
  virtual ~BenchObserver() = default;
  // Along the way (the CLI's stderr): the plan, a resumption, a stage beginning, and
  // "warning: ..." for an output that could not be made.
  virtual void note(const std::string& line) = 0;
  // The results (the CLI's stdout): the summary table, what was written where.
  virtual void report(const std::string& line) = 0;
  // A stretch of `total` items (the runs, then the videos), `alreadyDone` of them from before;
  // then each item as it finishes ("<stem>: coverage 0.512"), then the stretch's end.
  virtual void stretchStarted(std::size_t total, std::size_t alreadyDone) = 0;
  virtual void itemFinished(const std::string& what) = 0;
  virtual void stretchDone() = 0;
};

}  // namespace camcov::bench
