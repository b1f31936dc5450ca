#include "bench/run_bench.h"

#include <fmt/format.h>

#include <algorithm>

#include "batch/batch_plan.h"
#include "batch/batch_runner.h"
#include "batch/merge.h"
#include "camcov/version.h"
#include "records/atomic_file.h"
#include "util/counted.h"
#include "util/run_threads.h"

namespace camcov::bench {
namespace {

unsigned workersFor(unsigned jobs) {
  return jobs > 0 ? jobs : availableCores();
}

// The batch runner's calls, said to the bench's observer: where a resumed batch picks up,
// then a stretch of one item per job.
class JobsToObserver final : public batch::BatchObserver {
 public:
  JobsToObserver(BenchObserver& observer, std::string folder)
      : observer_(observer), folder_(std::move(folder)) {}
  void resuming(const batch::Resumption& r) override {
    if (r.alreadyDone > 0) observer_.note(batch::describeResumption(r, folder_));
    observer_.stretchStarted(r.total, r.alreadyDone);
  }
  void finished(const batch::BatchJob& job, const records::JobOutcome& outcome) override {
    observer_.itemFinished(outcome.failed ? fmt::format("{}: FAILED: {}", job.stem, outcome.error)
                                          : fmt::format("{}: coverage {:.3f}", job.stem,
                                                        outcome.summary.averageCoverage));
  }

 private:
  BenchObserver& observer_;
  std::string folder_;
};

std::size_t countFailed(const std::vector<records::JobOutcome>& outcomes) {
  return static_cast<std::size_t>(
      std::count_if(outcomes.begin(), outcomes.end(), [](const auto& j) { return j.failed; }));
}

}  // namespace

BenchResult runBench(const BenchRequest& request, BenchObserver& observer) {
  request.outputs.check();  // a bad --videos or --explorer fails now, not after the runs
  batch::BatchRequest plan{request.scenes,
                           request.methods,
                           request.seeds,
                           request.parameters,
                           batch::parseShard(request.shard),
                           request.command,
                           request.extraMethods,
                           request.duration >= 0.0};
  if (request.duration >= 0.0) plan.parameters.sim.duration = request.duration;
  batch::BatchPlan planned = batch::planBatch(plan, kVersion);
  request.outputs.referenceAmong(planned.manifest.methods);  // and a bad --reference too
  const records::BatchFolder folder(request.out);
  {
    records::NewFolderGuard created(folder.root());  // kept once the manifest is written
    batch::prepareFolder(folder, planned.manifest, request.force);
    created.keep();
  }
  const batch::Shard& shard = plan.shard;
  const unsigned workers = workersFor(request.jobs);
  observer.note(fmt::format(
      "camcov bench: {} x {} x {} = {}{} on {} -> {}",
      counted(planned.manifest.scenes.size(), "scene", "scenes"),
      counted(planned.manifest.methods.size(), "method", "methods"),
      counted(request.seeds, "seed", "seeds"), counted(planned.totalJobs, "job", "jobs"),
      shard.count > 1
          ? fmt::format(" (shard {}/{}: {})", shard.index + 1, shard.count, planned.jobs.size())
          : "",
      counted(workers, "worker", "workers"), request.out));
  batch::BatchRun run;
  {
    JobsToObserver jobs(observer, request.out);
    run = batch::runBatch(planned.jobs, folder, workers, jobs);
    observer.stretchDone();
  }
  BenchResult result;
  result.jobs = planned.jobs.size();
  result.failedJobs = countFailed(run.outcomes);
  if (shard.count > 1) {
    result.shard = true;
    observer.report(
        fmt::format("shard {}/{} done: {} jobs, {} failed. Combine the shards' folders "
                    "with `camcov merge DIR... --out DIR`.",
                    shard.index + 1, shard.count, result.jobs, result.failedJobs));
    return result;
  }
  result.summary = finishBench(folder, planned.manifest, run.outcomes, run.omplRuns,
                               request.outputs, workers, observer);
  result.failedJobs = result.summary.failures.size();  // with those of earlier sittings
  return result;
}

BenchResult mergeBench(const std::vector<std::string>& inputs, const std::string& out,
                       const BenchOutputOptions& outputs, const std::vector<std::string>& command,
                       BenchObserver& observer) {
  outputs.check();  // a bad --videos or --explorer fails before anything is copied
  const records::BatchFolder target(out);
  records::NewFolderGuard created(target.root());
  const records::BatchManifest manifest = batch::mergeFolders(inputs, target, command);
  const std::vector<records::JobOutcome> outcomes = target.allJobs();
  BenchResult result;
  result.jobs = outcomes.size();
  result.summary = finishBench(target, manifest, outcomes, {}, outputs, workersFor(0), observer);
  result.failedJobs = result.summary.failures.size();
  created.keep();
  return result;
}

}  // namespace camcov::bench
