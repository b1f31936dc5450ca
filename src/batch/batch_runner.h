#pragma once
// Runs a batch's jobs on a pool of worker threads (SPEC section 7): each job writes its own
// results file atomically the moment it finishes, so a killed batch loses only the jobs in
// flight; a job that throws is recorded as failed and the others go on.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "batch/run_job.h"
#include "records/batch_folder.h"
#include "records/batch_summary.h"

namespace camcov::batch {

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

// What a running batch tells its caller (the CLI draws a progress line, Python may report
// to a notebook). Calls never overlap: `finished` is called under the batch's lock.
class BatchObserver {
 public:
  virtual ~BatchObserver() = default;
  // Before any job runs: `alreadyDone` of `total` jobs were found finished in the folder.
  virtual void resuming(std::size_t alreadyDone, std::size_t total) = 0;
  virtual void finished(const BatchJob& job, const records::JobOutcome& outcome) = 0;
};

// Runs on `workers` threads (at least 1) every job whose results the folder does not hold
// yet for the same parameters and scene file (resume), writing each as it finishes, then
// the folder's timings (those of earlier runs kept).
BatchRun runBatch(const std::vector<BatchJob>& jobs, const records::BatchFolder& folder,
                  unsigned workers, BatchObserver& observer);

}  // namespace camcov::batch
