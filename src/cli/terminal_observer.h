#pragma once
// A bench's lines on the terminal: notes and progress on stderr (a live progress line on a
// terminal, one line per item in a log), results on stdout.
#include <mutex>
#include <optional>

#include "bench/bench_observer.h"
#include "cli/progress.h"

namespace camcov::cli {

class TerminalObserver final : public bench::BenchObserver {
 public:
  ~TerminalObserver() override { stretchDone(); }
  void note(const std::string& line) override;
  void report(const std::string& line) override;
  void stretchStarted(std::size_t total, std::size_t alreadyDone) override;
  void itemFinished(const std::string& what) override;
  void stretchDone() override;

 private:
  std::mutex mutex_;
  std::optional<Progress> progress_;
};

}  // namespace camcov::cli
