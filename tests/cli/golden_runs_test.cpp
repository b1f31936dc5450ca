// Golden runs: the exact results of a few runs of our own scenes, committed as fingerprints
// (like Box2D's expected hash), so a change that moves any number of any run is seen, not only
// a change that breaks determinism between two runs of the same build. When a change is meant
// to change results, update them with
//   scripts/update_golden_runs.sh
// and say in the commit what changed and why (docs/reliability.md, "Development").
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"
#include "util/fnv1a.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// Everything a run's results say, except where the file was read from and the tool version.
std::string fingerprint(const nlohmann::json& run) {
  const nlohmann::json kept = {{"scene", run.at("scene").at("hash")},
                               {"method", run.at("method")},
                               {"seed", run.at("seed")},
                               {"parameters", run.at("parameters")},
                               {"summary", run.at("summary")},
                               {"series", run.at("series")},
                               {"events", run.at("events")}};
  return fmt::format("{:016x}", fnv1a(kept.dump()));
}

TEST(GoldenRuns, OwnScenesGiveTheCommittedResults) {
  const fs::path goldenFile = testDataDir() / "golden_runs.json";
  nlohmann::json golden = nlohmann::json::parse(readFile(goldenFile));
  const bool update = std::getenv("CAMCOV_UPDATE_GOLDEN_RUNS") != nullptr;
  const ScratchDir dir;
  for (auto& entry : golden.at("runs")) {
    const std::string scene = entry.at("scene"), method = entry.at("method");
    const int seed = entry.at("seed");
    SCOPED_TRACE(fmt::format("{} {} seed {}", scene, method, seed));
    const auto r = runCamcov(fmt::format("run {} --method {} --seed {} --out {}",
                                         (ownScenesDir() / (scene + ".json")).string(), method,
                                         seed, dir.path().string()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto run = nlohmann::json::parse(
        readFile(dir / fmt::format("{}-{}-seed{}.json", scene, method, seed)));
    const std::string now = fingerprint(run);
    if (update) {
      entry["fingerprint"] = now;
      continue;
    }
    EXPECT_EQ(now, entry.at("fingerprint").get<std::string>())
        << "the results changed; if that is meant, run scripts/update_golden_runs.sh and say "
           "why in the commit";
  }
  if (update) {
    std::ofstream(goldenFile) << golden.dump(2) << "\n";
    GTEST_SKIP() << "updated " << goldenFile;
  }
}

}  // namespace
}  // namespace camcov::testing
