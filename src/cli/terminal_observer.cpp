#include "cli/terminal_observer.h"

#include <iostream>

namespace camcov::cli {

void TerminalObserver::note(const std::string& line) {
  const std::lock_guard lock(mutex_);
  std::cerr << line << "\n";
}

void TerminalObserver::report(const std::string& line) {
  const std::lock_guard lock(mutex_);
  std::cout << line << "\n";
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
