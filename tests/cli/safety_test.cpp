// The safety layer through the executable. `--set safety.enabled=false` gives back the runs camcov
// made before the safety layer existed, byte for byte in everything that describes the run (poses,
// goals, coverage, utilization, repulsion, reward, the sampled distances, the controller's events);
// the layer's additions (continuous-time distances, contact events) are left out of the comparison.
// The hashes were taken from runs of commit 22712ab, the last one without the layer:
//   camcov run ../shared/coverage_scenes/SCENE.json --method M --seed N
// then FNV-1a of the JSON dump of those keys, as computed below. The incremental terms (ebee9e3)
// made the reward's sums exact (reward/fixed_point_sum.h), which moves the last bits of most runs:
// the hashes since are of those runs with the layer off (dynamic1 local kept its bytes), taken the
// same way.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"
#include "util/fnv1a.h"

namespace camcov::testing {
namespace {

std::uint64_t runHash(const nlohmann::json& run) {
  nlohmann::json subset;
  for (const char* key : {"time", "coverage", "utilization", "repulsion", "reward",
                          "minObjectDistance", "minCameraDistance", "cameras", "goals"})
    subset[key] = run.at("series").at(key);
  subset["events"] = nlohmann::json::array();
  for (const auto& e : run.at("events")) {
    const std::string kind = e.at("kind");
    if (kind == "avoidable-contact" || kind == "unavoidable-contact") continue;
    nlohmann::json event = e;
    event.erase("reason");  // typed since, from what the detail said
    subset["events"].push_back(std::move(event));
  }
  return fnv1a(subset.dump());
}

struct Golden {
  const char* scene;
  const char* method;
  int seed;
  std::uint64_t hash;
};

class SafetyOff : public ::testing::TestWithParam<Golden> {};

TEST_P(SafetyOff, ReproducesTheRunsMadeBeforeTheSafetyLayer) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const Golden g = GetParam();
  const auto out = freshDir(fmt::format("safety-off-{}-{}", g.scene, g.method));
  const std::string args =
      fmt::format("run {}/{}.json --method {} --seed {} --out {}", publishedScenesDir().string(),
                  g.scene, g.method, g.seed, out.string());
  const auto off = runCamcov(args + " --set safety.enabled=false");
  ASSERT_EQ(off.exitCode, 0) << off.err;
  const auto file = out / fmt::format("{}-{}-seed{}.json", g.scene, g.method, g.seed);
  EXPECT_EQ(runHash(nlohmann::json::parse(readFile(file))), g.hash);

  // With the layer on (the default) the same run is another run, and keeps δ.
  const auto on = runCamcov(args);
  ASSERT_EQ(on.exitCode, 0) << on.err;
  const auto run = nlohmann::json::parse(readFile(file));
  if (std::string(g.scene) == "dynamic13") {
    EXPECT_NE(runHash(run), g.hash);
  }
  EXPECT_EQ(run["summary"]["avoidableContactTime"], 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Published, SafetyOff,
    ::testing::Values(Golden{"dynamic13", "paper", 1, 0xbc86539daad8a881ull},  // hit at 6 mm
                      Golden{"dynamic9", "paper", 2, 0x9054e287b5fc0a4full},   // 2.6 s below δ
                      Golden{"dynamic9", "local", 1, 0x49359c7832840ab4ull},
                      Golden{"dynamic1", "local", 1, 0xb973b74d9ebd39d4ull}),
    [](const auto& info) {
      return fmt::format("{}_{}_seed{}", info.param.scene, info.param.method, info.param.seed);
    });

// On our own scenes the layer leaves contacts only where a target outruns the cameras
// (docs/method.md). Each is unavoidable, begins with an event that says why, and the time
// below δ in the rows adds up to the summary's.
TEST(SafetyOn, AnOutrunCameraHasOnlyExplainedUnavoidableContacts) {
  const auto out = freshDir("safety-on-fast-target");
  const auto r =
      runCamcov("run " + (ownScenesDir() / "dynamic_fast_target_slow_cameras.json").string() +
                " --method paper --seed 1 --out " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto run =
      nlohmann::json::parse(readFile(out / "dynamic_fast_target_slow_cameras-paper-seed1.json"));
  const auto& summary = run["summary"];
  EXPECT_EQ(summary["avoidableContactTime"], 0.0);
  EXPECT_GT(summary["unavoidableContactTime"].get<double>(), 0.0);
  int events = 0;
  for (const auto& e : run["events"]) {
    if (e["kind"] == "avoidable-contact") ADD_FAILURE() << e.dump();
    if (e["kind"] != "unavoidable-contact") continue;
    ++events;
    EXPECT_EQ(e["reason"], "outpaced") << e.dump();  // a 3 m/s target, 0.8 m/s cameras
    EXPECT_NE(e["detail"].get<std::string>().find("3.00 m/s"), std::string::npos) << e.dump();
  }
  EXPECT_EQ(events, summary["unavoidableContacts"].get<int>());
  EXPECT_GT(events, 0);
  double rows = 0.0;
  for (const auto& t : run["series"]["unavoidableContactTime"])
    rows += t.get<double>();
  EXPECT_NEAR(rows, summary["unavoidableContactTime"].get<double>(), 1e-12);
}

}  // namespace
}  // namespace camcov::testing
