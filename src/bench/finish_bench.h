#pragma once
// What a bench makes once its runs exist, for `camcov bench`, `camcov merge` and camcov.bench
// alike: the summary (JSON, CSV), the OMPL benchmark logs, the videos, the explorer pages,
// the offline optima, the report, and the summary table said to the observer.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "bench/bench_observer.h"
#include "records/batch_folder.h"
#include "records/batch_summary.h"
#include "records/ompl_benchmark_log.h"
#include "records/video_choice.h"

namespace camcov::bench {

// What to make after the runs. The defaults are every front end's.
struct BenchOutputOptions {
  bool noReport = false;
  std::string videos = "median";    // videos/: none, median, best or all
  std::string explorer = "median";  // explore/<scene>.html: none, median or best
  std::string reference;            // the method the others are tested against; empty: the baseline
  std::int64_t optimumBudget = 200000;  // reward evaluations per optimum/<scene>.json; 0: none
  // InputError for a bad --videos.
  records::VideoChoice videoChoice() const { return records::parseVideoChoice(videos, "--videos"); }
  // InputError for a bad --explorer (all seeds of a scene on one page would not be read).
  records::VideoChoice explorerChoice() const;
  // Those checks and the optimum's budget in [0, 2^40] (Python passes it unchecked by a
  // command line), before any job runs.
  void check() const;
  // The reference among `methods`; InputError if --reference names another.
  std::string referenceAmong(const std::vector<std::string>& methods) const;
};

// Writes everything above into `folder`; videos and optima are made on `workers` threads.
// `omplRuns`: what the OMPL logs take of the runs the batch kept in memory (BatchRun), the
// others read back. Returns the summary (its failures are the jobs that failed).
records::BatchSummary finishBench(const records::BatchFolder& folder,
                                  const records::BatchManifest& manifest,
                                  const std::vector<records::JobOutcome>& outcomes,
                                  const std::map<std::string, records::OmplRun>& omplRuns,
                                  const BenchOutputOptions& options, unsigned workers,
                                  BenchObserver& observer);

}  // namespace camcov::bench
