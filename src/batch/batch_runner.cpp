#include "batch/batch_runner.h"

#include <fmt/format.h>
#include <sys/stat.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <ctime>
#include <exception>
#include <mutex>
#include <optional>

#include "records/run_files.h"
#include "util/interruption.h"
#include "util/run_threads.h"
#include "util/worker_pool.h"

namespace camcov::batch {

namespace {

std::string utcMinute(std::int64_t seconds, const char* format) {
  const std::time_t t = seconds;
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, format, &tm);
  return text;
}

}  // namespace

std::string describeResumption(const Resumption& r, const std::string& folder) {
  if (r.alreadyDone == 0) return "";
  const std::string from = utcMinute(r.earliest, "%F %H:%M");
  const std::string to = utcMinute(r.latest, "%F %H:%M");
  // "2026-11-26 14:02 to 14:10": the second date only when it is another day.
  const std::string when =
      from == to ? from
                 : from + " to " + (from.substr(0, 10) == to.substr(0, 10) ? to.substr(11) : to);
  return fmt::format("{} of {} jobs already done in {} (written {} UTC); running the other {}",
                     r.alreadyDone, r.total, folder, when, r.total - r.alreadyDone);
}

BatchRun runBatch(const std::vector<BatchJob>& jobs, const records::BatchFolder& folder,
                  unsigned workers, BatchObserver& observer) {
  BatchRun batch;
  batch.outcomes.resize(jobs.size());
  std::vector<std::size_t> pending;
  Resumption resumption{0, jobs.size(), 0, 0};
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    const BatchJob& job = jobs[i];
    if (auto done = folder.finishedJob(job.stem, job.spec.parameters, job.sceneHash)) {
      batch.outcomes[i] = std::move(*done);
      struct stat s {};
      if (::stat(folder.runFile(job.stem).c_str(), &s) == 0) {
        const std::int64_t written = s.st_mtime;
        resumption.earliest =
            resumption.alreadyDone == 0 ? written : std::min(resumption.earliest, written);
        resumption.latest = std::max(resumption.latest, written);
      }
      ++resumption.alreadyDone;
    } else {
      pending.push_back(i);
    }
  }
  observer.resuming(resumption);
  // Fewer jobs than workers: each run gets the threads left over for its own work (the same
  // results with any number), until the batch ends.
  struct RunThreadsDuringBatch {
    unsigned before = runThreads();
    explicit RunThreadsDuringBatch(unsigned threads) { setRunThreads(threads); }
    ~RunThreadsDuringBatch() { setRunThreads(before); }
  } const runThreadsDuringBatch(
      pending.empty() ? runThreads()
                      : std::max(runThreads(), static_cast<unsigned>(workers / pending.size())));
  std::mutex mutex;
  std::size_t keptBytes = 0;             // of batch.omplRuns
  std::atomic<bool> interrupted{false};  // once set, the jobs not started are left for a resume
  forEachOnWorkers(pending.size(), workers, [&](std::size_t k) {
    if (interrupted) return;
    const BatchJob& job = jobs[pending[k]];
    records::JobOutcome outcome{job.scene, job.spec.method, job.spec.seed, false, "", {}};
    std::optional<records::OmplRun> omplRun;
    const auto wallStart = std::chrono::steady_clock::now();
    const double cpuStart = cpuSecondsWithJoinedThreads();
    try {
      throwIfInterrupted();
      const records::RunRecord run = runJob(job.spec);
      // Not flushed run by run (a twentieth of the protocol's time): a resume runs again a run
      // whose files a power cut left empty or short, and the file system is flushed once below.
      records::writeRunFiles(run, folder.runsDir(), records::Durability::Deferred);
      folder.removeFailure(job.stem);
      outcome.summary = run.summary;
      omplRun = records::omplRunOf(run);
    } catch (const Interrupted&) {
      interrupted = true;  // not the job's failure: it runs again on a resume
      return;
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
        cpuSecondsWithJoinedThreads() - cpuStart};
    const std::lock_guard lock(mutex);
    observer.finished(job, outcome);
    batch.outcomes[pending[k]] = std::move(outcome);
    batch.timings[job.stem] = timing;
    if (omplRun) {
      const std::size_t bytes =
          sizeof(records::OmplRun) + omplRun->progress.size() * sizeof(omplRun->progress.front());
      if (keptBytes + bytes <= kOmplRunsKeptBytes) {
        keptBytes += bytes;
        batch.omplRuns.emplace(job.stem, std::move(*omplRun));
      }
    }
  });
  records::flushFileSystemOf(folder.root());
  // The folder keeps the timings of every job it holds, from earlier runs too.
  auto timings = folder.readTimings();
  for (const auto& [stem, t] : batch.timings)
    timings[stem] = t;
  folder.writeTimings(timings);
  if (interrupted) throw Interrupted();
  return batch;
}

}  // namespace camcov::batch
