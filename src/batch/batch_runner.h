#pragma once
// Runs a batch's jobs on a pool of worker threads (SPEC section 7): each job writes its own
// results file atomically the moment it finishes, so a killed batch loses only the jobs in
// flight; a job that throws is recorded as failed and the others go on.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "batch/run_job.h"
#include "records/batch_folder.h"
#include "records/batch_summary.h"
#include "records/ompl_benchmark_log.h"

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
  // What the OMPL logs take of the jobs run now, by stem, as long as it fits in
  // kOmplRunsKeptBytes; the logs read the others back from their files.
  std::map<std::string, records::OmplRun> omplRuns;
};

// Memory a batch may hold for its OMPL logs: the 1,920 runs of the published protocol with
// our method take about 14 MB.
inline constexpr std::size_t kOmplRunsKeptBytes = std::size_t{32} << 20;

// Before any job runs: how many of the batch's jobs were found finished in the folder, and
// when their results were written (seconds since the epoch, of the files).
struct Resumption {
  std::size_t alreadyDone = 0;
  std::size_t total = 0;
  std::int64_t earliest = 0, latest = 0;  // 0 when nothing was reused
};
// "12 of 40 jobs already done in OUT (written 2026-11-26 14:02 to 14:10 UTC); running the
// other 28", or "" when nothing is reused: the line every caller prints.
std::string describeResumption(const Resumption& r, const std::string& folder);

// What a running batch tells its caller (the CLI draws a progress line, Python may report
// to a notebook). Calls never overlap: `finished` is called under the batch's lock.
class BatchObserver {
 public:
  virtual ~BatchObserver() = default;
  virtual void resuming(const Resumption& resumption) = 0;
  virtual void finished(const BatchJob& job, const records::JobOutcome& outcome) = 0;
};

// Runs on `workers` threads (at least 1) every job whose results the folder does not hold
// yet for the same parameters and scene file (resume), writing each as it finishes, then
// the folder's timings (those of earlier runs kept). Throws Interrupted (util/interruption.h)
// once the jobs in flight have stopped when the caller's check asks it to, with the finished
// jobs' files and timings written: a resume runs the rest.
BatchRun runBatch(const std::vector<BatchJob>& jobs, const records::BatchFolder& folder,
                  unsigned workers, BatchObserver& observer);

}  // namespace camcov::batch
