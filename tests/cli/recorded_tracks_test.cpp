// Runs of scenes whose targets come and go (recorded tracks): each step says how
// many targets are present, entering and leaving are events, averages leave out the steps
// with nothing to cover — and no method ever sees the future: a target that turns at t leaves
// every decision before t unchanged.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kScene = testDataDir() / "scenes_tracks" / "comes_and_goes.json";

nlohmann::json run(const fs::path& scene, const std::string& method, const fs::path& out) {
  const auto r = runCamcov("run " + scene.string() + " --method " + method +
                           " --seed 4 --duration 4 --set global.K=60 --out " + out.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(
      readFile(out / (scene.stem().string() + "-" + method + "-seed4.json")));
}

TEST(RecordedTracks, StepsCountThePresentEventsMarkEntriesAndAveragesSkipEmptySteps) {
  const ScratchDir dir;
  const nlohmann::json j = run(kScene, "paper", dir.path());
  const auto& series = j["series"];
  const auto& present = series["targetsPresent"];
  ASSERT_EQ(present.size(), series["time"].size());
  // Target 1 is there from 0.5 s to 2.5 s, target 0 from 1 s to 3 s (the steps are 0.1 s).
  for (std::size_t k = 0; k < present.size(); ++k) {
    const double t = series["time"][k].get<double>();
    const int expected =
        (t >= 0.5 - 1e-9 && t <= 2.5 + 1e-9) + (t >= 1.0 - 1e-9 && t <= 3.0 + 1e-9);
    EXPECT_EQ(present[k].get<int>(), expected) << "t = " << t;
    if (expected == 0) {
      EXPECT_EQ(series["coverage"][k].get<double>(), 0.0) << "t = " << t;
    }
  }
  std::vector<std::pair<double, std::string>> entries;
  for (const auto& e : j["events"]) {
    const std::string kind = e["kind"];
    if (kind == "target-appears" || kind == "target-leaves")
      entries.emplace_back(e["time"].get<double>(), kind + " " + e["detail"].get<std::string>());
  }
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_NEAR(entries[0].first, 0.5, 1e-9);
  EXPECT_EQ(entries[0].second, "target-appears target 1 enters the scene");
  EXPECT_NEAR(entries[1].first, 1.0, 1e-9);
  EXPECT_NEAR(entries[2].first, 2.6, 1e-9);
  EXPECT_EQ(entries[2].second, "target-leaves target 1 leaves the scene");
  EXPECT_NEAR(entries[3].first, 3.1, 1e-9);

  // The average over the intervals with something to cover at both ends, from the series.
  double sum = 0.0, span = 0.0;
  int empty = 0;
  for (std::size_t k = 0; k < present.size(); ++k) {
    if (present[k] == 0) ++empty;
    if (k == 0 || present[k] == 0 || present[k - 1] == 0) continue;
    sum +=
        0.5 * (series["coverage"][k - 1].get<double>() + series["coverage"][k].get<double>()) * 0.1;
    span += 0.1;
  }
  EXPECT_NEAR(j["summary"]["averageCoverage"].get<double>(), sum / span, 1e-12);
  EXPECT_EQ(j["summary"]["stepsWithoutTargets"], empty);
}

TEST(RecordedTracks, NoMethodSeesTheFuture) {
  // The same scene, but target 0 turns the other way at t = 2 s.
  const ScratchDir dir;
  nlohmann::json other = nlohmann::json::parse(readFile(kScene));
  other["targets"][0]["track"]["samples"][2] = {3, 0, -4};
  const fs::path turned = dir / "turned.json";
  std::ofstream(turned) << other.dump(2);
  for (const std::string method : {"paper", "local", "camcov", "nearest-unseen"}) {
    const nlohmann::json a = run(kScene, method, dir / ("a-" + method));
    const nlohmann::json b = run(turned, method, dir / ("b-" + method));
    const auto& ta = a["series"]["time"];
    std::size_t same = 0;
    for (std::size_t k = 0; k < ta.size(); ++k) {
      if (ta[k].get<double>() > 2.0 + 1e-9) break;
      same = k;
      for (const char* key : {"coverage", "utilization", "reward"})
        EXPECT_EQ(a["series"][key][k], b["series"][key][k])
            << method << " " << key << " at step " << k;
      for (std::size_t c = 0; c < a["series"]["cameras"].size(); ++c) {
        EXPECT_EQ(a["series"]["cameras"][c][k], b["series"]["cameras"][c][k])
            << method << " camera " << c << " step " << k;
        EXPECT_EQ(a["series"]["goals"][c][k], b["series"]["goals"][c][k])
            << method << " goal " << c << " step " << k;
      }
    }
    // Decisions up to t = 2 s, and the poses they lead to one step later, are the same.
    for (std::size_t c = 0; c < a["series"]["cameras"].size(); ++c)
      EXPECT_EQ(a["series"]["cameras"][c][same + 1], b["series"]["cameras"][c][same + 1]) << method;
    const auto before = [](const nlohmann::json& run) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& e : run["events"])
        if (e["time"].get<double>() <= 2.0 + 1e-9) out.push_back(e);
      return out;
    };
    EXPECT_EQ(before(a), before(b)) << method;
    // And the scenes do differ afterwards, so the comparison could fail.
    EXPECT_NE(a["series"]["coverage"], b["series"]["coverage"]) << method;
  }
}

}  // namespace
}  // namespace camcov::testing
