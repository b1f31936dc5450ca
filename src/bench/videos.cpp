#include "bench/videos.h"

#include <fmt/format.h>

#include <atomic>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bench_observer.h"
#include "records/run_files.h"
#include "util/worker_pool.h"
#include "viz/run_replay.h"

namespace camcov::bench {

namespace fs = std::filesystem;

OutputBatch writeBenchVideos(const records::BatchFolder& folder,
                             std::span<const records::VideoRun> runs, unsigned workers,
                             BenchObserver& observer) {
  OutputBatch batch;
  if (runs.empty()) return batch;
  const fs::path dir = folder.videosDir();  // made by the first video's encoder

  // A video is up to date if it is newer than its run's results file: a run done again
  // (other parameters, --force, a changed scene) gets a new video.
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string stem = records::runStem(runs[i].scene, runs[i].method, runs[i].seed);
    std::error_code ec;
    const auto video = fs::last_write_time(folder.videoFile(stem), ec);
    if (!ec && video >= fs::last_write_time(folder.runFile(stem))) {
      ++batch.upToDate;
    } else {
      pending.push_back(i);
    }
  }
  observer.note(fmt::format("videos: {} to write, {} up to date in {}", pending.size(),
                            batch.upToDate, dir.string()));
  observer.stretchStarted(runs.size(), batch.upToDate);
  std::atomic<std::size_t> written{0};
  OutputProblems problems;
  forEachOnWorkers(pending.size(), workers, [&](std::size_t k) {
    const records::VideoRun& chosen = runs[pending[k]];
    const std::string stem = records::runStem(chosen.scene, chosen.method, chosen.seed);
    // "videos/<stem>.mp4": the file, as seen from the results folder.
    const std::string shown = fs::relative(folder.videoFile(stem), folder.root()).string();
    std::string what;
    try {
      const records::RunRecord run = records::loadRunFile(folder.runFile(stem));
      const viz::RunScene scene = viz::loadRunScene(run.metadata);
      const std::size_t frames =
          viz::writeRunVideo(run, scene.scene, folder.videoFile(stem), viz::runVideoSettings(run));
      ++written;
      what =
          fmt::format("{}: {} frames{}", shown, frames,
                      scene.changed ? " (warning: the scene file has changed since the run)" : "");
    } catch (const std::exception& e) {
      what = fmt::format("{}: not written: {}", shown, e.what());
      problems.add(what);
    }
    observer.itemFinished(what);
  });
  observer.stretchDone();
  batch.failed = problems.report(observer);
  batch.written = written;
  return batch;
}

}  // namespace camcov::bench
