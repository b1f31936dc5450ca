#include "bench/output_batch.h"

#include <fmt/format.h>

#include "bench/bench_observer.h"
#include "util/counted.h"

namespace camcov::bench {

std::string OutputBatch::describe(std::string_view one, std::string_view many,
                                  const std::string& dir) const {
  std::string notes;
  if (upToDate > 0) notes += fmt::format("{} up to date", upToDate);
  if (failed > 0) notes += fmt::format("{}{} not written", notes.empty() ? "" : ", ", failed);
  return fmt::format("wrote {} in {}{}", counted(written, one, many), dir,
                     notes.empty() ? "" : " (" + notes + ")");
}

void OutputProblems::add(std::string problem) {
  const std::lock_guard lock(mutex_);
  problems_.push_back(std::move(problem));
}

std::size_t OutputProblems::report(BenchObserver& observer) const {
  const std::lock_guard lock(mutex_);
  for (const std::string& problem : problems_)
    observer.note("warning: " + problem);
  return problems_.size();
}

}  // namespace camcov::bench
