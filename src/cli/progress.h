#pragma once
// A bench's progress on stderr (bench/progress_count.h gives the text): on a terminal one live
// line, rewritten as items finish, in a log one plain line per finished item.
#include <string>

#include "bench/progress_count.h"

namespace camcov::cli {

class Progress {
 public:
  Progress(std::size_t total, std::size_t alreadyDone);
  // Thread-safe.
  void finished(const std::string& what);
  void close();

 private:
  bench::ProgressCount count_;
  bool terminal_;
};

}  // namespace camcov::cli
