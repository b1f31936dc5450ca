#include "bench/explorer_pages.h"

#include <fmt/format.h>

#include <map>

#include "bench/bench_observer.h"

#include "records/run_files.h"
#include "reports/explorer/explorer_page.h"
#include "util/input_error.h"

namespace camcov::bench {

OutputBatch writeBenchExplorers(const records::BatchFolder& folder,
                                std::span<const records::VideoRun> runs, BenchObserver& observer) {
  std::map<std::string, std::vector<std::filesystem::path>> byScene;  // in the runs' order
  for (const auto& run : runs)
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
