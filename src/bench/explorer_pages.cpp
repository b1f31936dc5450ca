#include "bench/explorer_pages.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "bench/bench_observer.h"
#include "control/methods.h"

#include "records/run_files.h"
#include "reports/explorer/explorer_page.h"
#include "util/input_error.h"

namespace camcov::bench {

OutputBatch writeBenchExplorers(const records::BatchFolder& folder,
                                std::span<const records::VideoRun> runs, BenchObserver& observer) {
  // Per scene, the runs side by side in the method order of every table and figure (paper,
  // local, camcov, then others by name), whatever order the runs come in.
  std::vector<std::string> methods;
  for (const auto& run : runs)
    methods.push_back(run.method);
  methods = control::inMethodOrder(methods);
  const auto rank = [&](const std::string& method) {
    return std::find(methods.begin(), methods.end(), method) - methods.begin();
  };
  std::vector<records::VideoRun> ordered(runs.begin(), runs.end());
  std::stable_sort(ordered.begin(), ordered.end(),
                   [&](const records::VideoRun& a, const records::VideoRun& b) {
                     return rank(a.method) < rank(b.method);
                   });
  std::map<std::string, std::vector<std::filesystem::path>> byScene;
  for (const auto& run : ordered)
    byScene[run.scene].push_back(folder.runFile(records::runStem(run.scene, run.method, run.seed)));
  OutputBatch batch;
  for (const auto& [scene, files] : byScene) {
    const std::filesystem::path page = folder.explorerPage(scene);
    try {
      std::filesystem::create_directories(page.parent_path());
      reports::explorer::writeExplorer(files, page);
      ++batch.written;
    } catch (const InputError& e) {
      observer.note(fmt::format("warning: no explorer page for {}: {}", scene, e.what()));
      ++batch.failed;
    }
  }
  return batch;
}

}  // namespace camcov::bench
