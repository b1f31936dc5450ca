#pragma once
// Runs a batch's jobs on a pool of worker threads (SPEC section 7): each job writes its own
// results file atomically the moment it finishes, so a killed batch loses only the jobs in
// flight; a job that throws is recorded as failed and the others go on.
#include <map>
#include <string>
#include <vector>

#include "cli/run_job.h"
#include "records/batch_folder.h"
#include "records/batch_summary.h"

namespace camcov::cli {

struct BatchJob {
  JobSpec spec;
  std::string scene;            // the scene's name
  std::uint64_t sceneHash = 0;  // of the scene file's bytes
  std::string stem;             // results file stem
};

struct BatchRun {
  std::vector<records::JobOutcome> outcomes;          // one per job, in job order
  std::map<std::string, records::JobTiming> timings;  // of the jobs run now, by stem
};

// `workers` threads (at least 1). Progress goes to stderr: a live line on a terminal, one
// line per finished job otherwise.
BatchRun runBatch(const std::vector<BatchJob>& jobs, const records::BatchFolder& folder,
                  unsigned workers);

}  // namespace camcov::cli
