#include "bench/optima.h"

#include <fmt/format.h>

#include <atomic>
#include <exception>
#include <string>
#include <vector>

#include "batch/scene_optimum.h"
#include "bench/bench_observer.h"
#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "records/optimum_file.h"
#include "scene/scene_loader.h"
#include "util/worker_pool.h"

namespace camcov::bench {

namespace {

// An optimum file made for this scene file, with these parameters and budget, at t = 0 from
// the bench's seed: what the search below would write again.
bool isCurrent(const std::filesystem::path& file, const records::SceneEntry& scene,
               const params::Parameters& parameters, std::int64_t budget) {
  if (!std::filesystem::exists(file)) return false;
  try {
    const records::OptimumFile found = records::loadOptimumFile(file);
    return found.sceneHash == scene.hash && found.budget == budget && found.time == 0.0 &&
           found.seed == batch::kBenchOptimumSeed &&
           params::toJson(found.parameters) == params::toJson(parameters);
  } catch (const std::exception&) {
    return false;  // unreadable: search again, the new file replaces it atomically
  }
}

}  // namespace

OutputBatch writeBenchOptima(const records::BatchFolder& folder,
                             const records::BatchManifest& manifest, std::int64_t budget,
                             unsigned workers, BenchObserver& observer) {
  OutputBatch batch;
  if (budget <= 0) return batch;
  // Each scene that holds still, with its one reading, which the search takes on.
  std::vector<std::pair<const records::SceneEntry*, scene::SceneFile>> pending;
  OutputProblems problems;
  for (const records::SceneEntry& entry : manifest.scenes) {
    try {
      scene::SceneFile file = scene::loadSceneFile(entry.file);
      if (!file.scene.holdsStill()) continue;
      if (isCurrent(folder.optimumFile(entry.name), entry, manifest.parameters, budget)) {
        ++batch.upToDate;
      } else {
        pending.emplace_back(&entry, std::move(file));
      }
    } catch (const std::exception& e) {
      problems.add(fmt::format("optimum/{}.json: not written: {}", entry.name, e.what()));
    }
  }
  std::atomic<std::size_t> written{0};
  forEachOnWorkers(pending.size(), workers, [&](std::size_t k) {
    const auto& [entry, file] = pending[k];
    try {
      const records::OptimumFile found = batch::searchSceneOptimum(
          file, entry->file, manifest.parameters, 0.0, budget, batch::kBenchOptimumSeed);
      records::writeFileAtomically(folder.optimumFile(entry->name),
                                   records::optimumToJson(found).dump(1) + "\n");
      ++written;
    } catch (const std::exception& e) {
      problems.add(fmt::format("optimum/{}.json: not written: {}", entry->name, e.what()));
    }
  });
  batch.failed = problems.report(observer);
  batch.written = written;
  return batch;
}

}  // namespace camcov::bench
