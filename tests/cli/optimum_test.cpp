// `camcov optimum`: the offline reference for a scene at one instant, written
// atomically with what the search did, its poses in the format `camcov inspect --cameras`
// reads (and inspect agrees with its coverage); bad requests exit 2 and write nothing.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <numeric>
#include <vector>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

const std::string kScene = (ownScenesDir() / "static_target_ring.json").string();

TEST(CliOptimum, WritesTheBestTeamHowItWasFoundAndPosesInspectAgreesWith) {
  const ScratchDir dir;
  const fs::path out = dir / "o" / "ring.json", poses = dir / "o" / "poses.json";
  const auto r = runCamcov("optimum " + kScene + " --budget 20000 --seed 3 -o " + out.string() +
                           " --poses " + poses.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("static_target_ring at t = 0 s: coverage"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(readFile(out));
  EXPECT_EQ(j["format"], "camcov-optimum/1");
  EXPECT_EQ(j["scene"]["name"], "static_target_ring");
  EXPECT_EQ(j["budget"], 20000);
  EXPECT_GE(j["evaluations"].get<long long>(), 20000);
  const double coverage = j["best"]["coverage"];
  EXPECT_GT(coverage, 0.0);
  EXPECT_LE(coverage, 1.0);
  ASSERT_FALSE(j["curve"].empty());
  EXPECT_EQ(j["curve"].back()["coverage"], coverage);
  EXPECT_EQ(j["found"]["evaluations"], j["curve"].back()["evaluations"]);

  const auto inspect = runCamcov("inspect " + kScene + " --json --cameras " + poses.string());
  ASSERT_EQ(inspect.exitCode, 0) << inspect.err;
  const auto seen = nlohmann::json::parse(inspect.out);
  EXPECT_NEAR(seen["coverage"].get<double>(), coverage, 1e-9);

  const fs::path again = dir / "again.json";
  ASSERT_EQ(
      runCamcov("optimum " + kScene + " --budget 20000 --seed 3 -o " + again.string()).exitCode, 0);
  EXPECT_EQ(readFile(out), readFile(again)) << "the same seed, the same file";
}

// The travel estimate, by hand: every way of giving the four cameras the four poses, the one
// of least summed time (what the Hungarian method minimizes), its longest time; each time the
// longer of driving straight at v_max and turning the shorter way at γ̇_max.
TEST(CliOptimum, SaysHowLongTheTeamNeedsFromItsStartAsEveryAssignmentByHandDoes) {
  const ScratchDir dir;
  const fs::path out = dir / "ring.json";
  const auto r = runCamcov("optimum " + kScene + " --budget 5000 -o " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(readFile(out));
  const auto scene = nlohmann::json::parse(readFile(kScene));
  const auto& poses = j["best"]["poses"];
  const std::size_t m = poses.size();
  ASSERT_EQ(m, scene["cameras"].size());
  const auto timeOf = [&](std::size_t camera, std::size_t pose) {
    const auto& c = scene["cameras"][camera];
    double x = 0, y = 0;
    std::sscanf(c["pos"].get<std::string>().c_str(), "POINT(%lf %lf)", &x, &y);
    const auto& p = poses[pose];
    double turn = std::fmod(std::abs(p["yaw_deg"].get<double>() - c["angle"].get<double>()), 360.0);
    turn = std::min(turn, 360.0 - turn) * std::numbers::pi / 180.0;
    return std::max(std::hypot(p["x"].get<double>() - x, p["y"].get<double>() - y) /
                        c["maxVelocity"].get<double>(),
                    turn / c["maxAngularVelocity"].get<double>());
  };
  std::vector<std::size_t> order(m);
  std::iota(order.begin(), order.end(), 0);
  double leastSum = 1e300, itsLongest = 0.0;
  do {
    double sum = 0.0, longest = 0.0;
    for (std::size_t c = 0; c < m; ++c) {
      sum += timeOf(c, order[c]);
      longest = std::max(longest, timeOf(c, order[c]));
    }
    if (sum < leastSum) {
      leastSum = sum;
      itsLongest = longest;
    }
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_NEAR(j["travelTime"].get<double>(), itsLongest, 1e-9);
  EXPECT_NE(r.out.find(fmt::format("needs about {:.1f} s", itsLongest)), std::string::npos)
      << r.out;
}

TEST(CliOptimum, BadRequestsExitTwoAndWriteNothing) {
  const ScratchDir dir;
  const fs::path out = dir / "never.json";
  for (const std::string& args :
       std::vector<std::string>{"/nonexistent.json", kScene + " --budget 0", kScene + " --time -1",
                                kScene + " --set global.K=0"}) {
    SCOPED_TRACE(args);
    const auto r = runCamcov("optimum " + args + " -o " + out.string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(r.err.empty());
  }
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace camcov::testing
