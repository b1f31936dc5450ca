// Runs of a scene with importance weights (docs/scene-format.md, "Importance weights"): both
// coverages recorded, the reward taking the weighted one unless told otherwise, and inspect's
// weighted coverage against the sum over its own segments and weights.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kScene = ownScenesDir() / "weighted_stage_and_walkers.json";

nlohmann::json run(const fs::path& scene, const fs::path& out, const std::string& extra = "") {
  const auto r = runCamcov("run " + scene.string() + " --method local --seed 2 --duration 6 " +
                           extra + " --out " + out.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(readFile(out / (scene.stem().string() + "-local-seed2.json")));
}

// λ1 · c + λ2 · utilization − λ3 · repulsion with the default λ, at step k.
double rewardWith(const nlohmann::json& series, const char* coverage, std::size_t k) {
  return 1.0 * series[coverage][k].get<double>() + 0.2 * series["utilization"][k].get<double>() -
         1.0 * series["repulsion"][k].get<double>();
}

TEST(WeightedScene, RunsRecordWeightedAndPlainCoverageAndTheRewardTakesTheWeighted) {
  const ScratchDir dir;
  const nlohmann::json j = run(kScene, dir.path());
  const auto& series = j["series"];
  ASSERT_TRUE(series.contains("weightedCoverage"));
  ASSERT_EQ(series["weightedCoverage"].size(), series["coverage"].size());
  bool differ = false;
  for (std::size_t k = 0; k < series["time"].size(); ++k) {
    EXPECT_NEAR(series["reward"][k].get<double>(), rewardWith(series, "weightedCoverage", k),
                1e-12);
    differ |= series["weightedCoverage"][k] != series["coverage"][k];
  }
  EXPECT_TRUE(differ) << "the weights changed nothing";
  EXPECT_TRUE(j["summary"].contains("averageWeightedCoverage"));
  EXPECT_TRUE(j["summary"].contains("finalWeightedCoverage"));
  const std::string csv = readFile(dir / "weighted_stage_and_walkers-local-seed2.csv");
  EXPECT_NE(csv.find(",unavoidable_contact_time,weighted_coverage,cam0_x"), std::string::npos);
}

TEST(WeightedScene, ThePlainObjectiveStillRecordsWeightedCoverage) {
  const ScratchDir dir;
  const nlohmann::json j = run(kScene, dir.path(), "--set reward.weighted=false");
  const auto& series = j["series"];
  ASSERT_TRUE(series.contains("weightedCoverage"));
  for (std::size_t k = 0; k < series["time"].size(); ++k)
    EXPECT_NEAR(series["reward"][k].get<double>(), rewardWith(series, "coverage", k), 1e-12);
}

TEST(WeightedScene, ScenesWithoutWeightsRecordNoWeightedCoverage) {
  const ScratchDir dir;
  const nlohmann::json j = run(ownScenesDir() / "fig1_example.json", dir.path());
  EXPECT_FALSE(j["series"].contains("weightedCoverage"));
  EXPECT_FALSE(j["summary"].contains("averageWeightedCoverage"));
}

TEST(WeightedScene, InspectsWeightedCoverageIsItsSegmentsWeightedSum) {
  // At t = 7 s the walkers are under way: their fronts weigh more.
  const auto r = runCamcov("inspect " + kScene.string() + " --time 7 --json");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  double seen = 0.0, total = 0.0;
  std::set<double> walkerWeights;
  for (const auto& s : j["segments"]) {
    const double w = s["weight"].get<double>(), length = s["length"].get<double>();
    total += w * length;
    if (!s["visibleBy"].empty()) seen += w * length;
    if (s["target"] == 1) walkerWeights.insert(w);
  }
  // Divided by the largest weight at the instant, the stage's 4: the walker's front 3/4, the rest
  // of it 1/4.
  EXPECT_EQ(walkerWeights, (std::set<double>{0.25, 0.75}));
  EXPECT_NEAR(j["weightedCoverage"].get<double>(), seen / total, 1e-12);
  EXPECT_NE(j["weightedCoverage"], j["coverage"]);
}

TEST(WeightedScene, StateGivesEachTargetsWeightsNowFrontIncluded) {
  // At t = 3 s the first walker goes +x along y = −4: its two edges facing +x lead.
  const auto r = runCamcov("state " + kScene.string() + " --time 3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["targets"][0]["edgeWeights"], (nlohmann::json{1.0, 0.25, 0.25, 0.25}));
  EXPECT_EQ(j["targets"][1]["edgeWeights"],
            (nlohmann::json{0.75, 0.25, 0.25, 0.25, 0.25, 0.25, 0.25, 0.75}));
}

}  // namespace
}  // namespace camcov::testing
