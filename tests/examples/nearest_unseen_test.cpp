// The example method of examples/: registered by its one line, run by the simulator like the
// built-in methods, and by `camcov bench` beside them when asked for by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <numeric>
#include <set>

#include "control/methods.h"
#include "sim/simulator.h"
#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/small_worlds.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

class Coverage final : public sim::Recorder {
 public:
  void step(const sim::StepRecord& r) override { coverage.push_back(r.terms.coverage); }
  std::vector<double> coverage;
};

TEST(NearestUnseen, IsRegisteredAsAnExampleOutsideTheDefaultBatch) {
  const control::Method* m = control::findMethod("nearest-unseen");
  ASSERT_NE(m, nullptr);
  EXPECT_EQ(m->role, control::Role::example);
  const auto defaults = control::defaultMethods();
  EXPECT_EQ(std::count(defaults.begin(), defaults.end(), "nearest-unseen"), 0);
  EXPECT_EQ(defaults, (std::vector<std::string>{"paper", "local", "camcov"}));
}

TEST(NearestUnseen, CamerasLookingAwayTurnToTheTargetAndSeeIt) {
  // Both cameras of this scene start looking away from the only target (coverage 0).
  const scene::Scene s = sceneFromJson(kOneTargetScene);
  params::Parameters p;
  p.sim.duration = 8.0;
  const auto controller = control::requireMethod("nearest-unseen").make(s, p, 1);
  Coverage log;
  sim::simulate(s, p, *controller, log);
  EXPECT_EQ(log.coverage.front(), 0.0);
  // Over the last two seconds, each camera stands in front of its own side of the square: about
  // half of it (a camera at an edge's end can lose a sliver to the other's wedge and back).
  const auto last = log.coverage.end() - 20;
  EXPECT_GE(std::accumulate(last, log.coverage.end(), 0.0) / 20, 0.45);
}

TEST(NearestUnseen, RunsInTheBatchBesideTheBuiltInMethodsAndIsComparedWithTheBaseline) {
  const fs::path out = freshDir("examples-bench");
  const auto r = runCamcov("bench --scenes " + (testDataDir() / "scenes").string() +
                           " --methods paper,local,nearest-unseen --seeds 2 --duration 2"
                           " --set global.K=30 --set planner.T2=0.05 --videos none --out " +
                           out.string());
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(fs::exists(out / "runs" / "tiny_static-nearest-unseen-seed2.json"));
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_EQ(summary["reference"], "local");
  std::set<std::string> compared;
  for (const auto& t : summary["totals"])
    compared.insert(t["method"].get<std::string>());
  EXPECT_EQ(compared, (std::set<std::string>{"paper", "nearest-unseen"}));
  const std::string report = readFile(out / "report.html");
  EXPECT_NE(report.find("nearest unseen edge (example)"), std::string::npos);
  EXPECT_NE(report.find("#2ca02c"), std::string::npos) << "drawn in its own colour";
}

TEST(NearestUnseen, AnotherReferenceIsChosenWithReferenceAndAnUnknownOneIsRefused) {
  const fs::path out = freshDir("examples-reference");
  const std::string args = "bench --scenes " + (testDataDir() / "scenes").string() +
                           " --methods local,nearest-unseen --seeds 1 --duration 1 --videos none"
                           " --no-report --out " +
                           out.string();
  const auto bad = runCamcov(args + " --reference paper");
  EXPECT_EQ(bad.exitCode, 2) << bad.err;
  EXPECT_NE(bad.err.find("--reference paper: not among the batch's methods"), std::string::npos)
      << bad.err;
  EXPECT_FALSE(fs::exists(out / "runs")) << "refused before any job ran";
  ASSERT_EQ(runCamcov(args + " --reference nearest-unseen").exitCode, 0);
  const auto summary = nlohmann::json::parse(readFile(out / "summary.json"));
  EXPECT_EQ(summary["reference"], "nearest-unseen");
}

}  // namespace
}  // namespace camcov::testing
