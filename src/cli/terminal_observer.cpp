#include "cli/terminal_observer.h"

#include <iostream>

namespace camcov::cli {

// Every line leaves as it is said. With stdout and stderr on one pipe (`2>&1 | cat`, a CI log)
// stdout is block-buffered: a result still in its buffer would come out below the notes and
// progress said after it. Writing to std::cerr happens to flush std::cout first (the streams
// are tied), but the progress lines bypass std::cerr (progress.cpp), so nothing is left to it.
void TerminalObserver::note(const std::string& line) {
  const std::lock_guard lock(mutex_);
  std::cerr << line << std::endl;
}

void TerminalObserver::report(const std::string& line) {
  const std::lock_guard lock(mutex_);
  std::cout << line << std::endl;
}

void TerminalObserver::stretchStarted(std::size_t total, std::size_t alreadyDone) {
  const std::lock_guard lock(mutex_);
  progress_.emplace(total, alreadyDone);
}

void TerminalObserver::itemFinished(const std::string& what) {
  const std::lock_guard lock(mutex_);
  if (progress_) progress_->finished(what);
}

void TerminalObserver::stretchDone() {
  const std::lock_guard lock(mutex_);
  if (progress_) progress_->close();
  progress_.reset();
}

}  // namespace camcov::cli
