#include "cli/batch_runner.h"

#include <fmt/format.h>
#include <time.h>

#include <chrono>
#include <exception>
#include <mutex>

#include "cli/progress.h"
#include "cli/worker_pool.h"
#include "records/run_files.h"

namespace camcov::cli {

namespace {

double threadCpuSeconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

BatchRun runBatch(const std::vector<BatchJob>& jobs, const records::BatchFolder& folder,
                  unsigned workers) {
  BatchRun batch;
  batch.outcomes.resize(jobs.size());
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const BatchJob& job = jobs[i];
    if (auto done = folder.finishedJob(job.stem, job.spec.parameters, job.sceneHash)) {
      batch.outcomes[i] = std::move(*done);
    } else {
      pending.push_back(i);
    }
  }
  if (jobs.size() != pending.size()) {
    std::fprintf(stderr, "%zu of %zu jobs already done in %s; running the other %zu\n",
                 jobs.size() - pending.size(), jobs.size(), folder.root().c_str(), pending.size());
  }
  Progress progress(jobs.size(), jobs.size() - pending.size());
  std::mutex mutex;
  forEachOnWorkers(pending.size(), workers, [&](std::size_t k) {
    const BatchJob& job = jobs[pending[k]];
    records::JobOutcome outcome{job.scene, job.spec.method, job.spec.seed, false, "", {}};
    const auto wallStart = std::chrono::steady_clock::now();
    const double cpuStart = threadCpuSeconds();
    std::string what;
    try {
      const records::RunRecord run = runJob(job.spec);
      records::writeRunFiles(run, folder.runsDir());
      folder.removeFailure(job.stem);
      outcome.summary = run.summary;
      what = fmt::format("{}: coverage {:.3f}", job.stem, run.summary.averageCoverage);
    } catch (const std::exception& e) {
      outcome.failed = true;
      outcome.error = e.what();
      what = fmt::format("{}: FAILED: {}", job.stem, e.what());
      try {
        folder.writeFailure(job.stem, outcome);
      } catch (const std::exception& again) {  // e.g. the disk is full: say so, go on
        what += fmt::format(" (not recorded: {})", again.what());
      }
    }
    const records::JobTiming timing{
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count(),
        threadCpuSeconds() - cpuStart};
    {
      const std::lock_guard lock(mutex);
      batch.outcomes[pending[k]] = std::move(outcome);
      batch.timings[job.stem] = timing;
    }
    progress.finished(what);
  });
  progress.close();
  return batch;
}

}  // namespace camcov::cli
