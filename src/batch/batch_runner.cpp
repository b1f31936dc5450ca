#include "batch/batch_runner.h"

#include <fmt/format.h>
#include <time.h>

#include <chrono>
#include <exception>
#include <mutex>

#include "records/run_files.h"
#include "util/worker_pool.h"

namespace camcov::batch {

namespace {

double threadCpuSeconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

BatchRun runBatch(const std::vector<BatchJob>& jobs, const records::BatchFolder& folder,
                  unsigned workers, BatchObserver& observer) {
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
  observer.resuming(jobs.size() - pending.size(), jobs.size());
  std::mutex mutex;
  forEachOnWorkers(pending.size(), workers, [&](std::size_t k) {
    const BatchJob& job = jobs[pending[k]];
    records::JobOutcome outcome{job.scene, job.spec.method, job.spec.seed, false, "", {}};
    const auto wallStart = std::chrono::steady_clock::now();
    const double cpuStart = threadCpuSeconds();
    try {
      const records::RunRecord run = runJob(job.spec);
      records::writeRunFiles(run, folder.runsDir());
      folder.removeFailure(job.stem);
      outcome.summary = run.summary;
    } catch (const std::exception& e) {
      outcome.failed = true;
      outcome.error = e.what();
      try {
        folder.writeFailure(job.stem, outcome);
      } catch (const std::exception& again) {  // e.g. the disk is full: say so, go on
        outcome.error += fmt::format(" (not recorded: {})", again.what());
      }
    }
    const records::JobTiming timing{
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count(),
        threadCpuSeconds() - cpuStart};
    const std::lock_guard lock(mutex);
    observer.finished(job, outcome);
    batch.outcomes[pending[k]] = std::move(outcome);
    batch.timings[job.stem] = timing;
  });
  // The folder keeps the timings of every job it holds, from earlier runs too.
  auto timings = folder.readTimings();
  for (const auto& [stem, t] : batch.timings)
    timings[stem] = t;
  folder.writeTimings(timings);
  return batch;
}

}  // namespace camcov::batch
