// `camcov run` end to end: files written, determinism, bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

const std::string kScene = (ownScenesDir() / "fig1_example.json").string();

TEST(CliRun, WritesJsonAndCsvAndPrintsAverages) {
  const fs::path out = freshDir("basic");
  const auto r =
      runCamcov("run " + kScene + " --method local --seed 3 --duration 2 --out " + out.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("average coverage"), std::string::npos);
  const auto j = nlohmann::json::parse(readFile(out / "fig1_example-local-seed3.json"));
  EXPECT_EQ(j["format"], "camcov-run/2");
  EXPECT_EQ(j["method"], "local");
  EXPECT_EQ(j["seed"], 3);
  EXPECT_EQ(j["parameters"]["global"]["K"], 500) << "every parameter is in the metadata";
  EXPECT_EQ(j["series"]["time"].size(), 21u);
  const std::string csv = readFile(out / "fig1_example-local-seed3.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 22);
}

// An imported recording's window is its scene's "duration": `camcov run` and `camcov bench` run
// for that long unless the command asks for another length.
TEST(CliRun, AScenesOwnDurationIsTheRunsUnlessTheCommandSaysOtherwise) {
  const fs::path out = freshDir("own_duration");
  auto scene = nlohmann::json::parse(readFile(kScene));
  scene["duration"] = 1.5;
  const fs::path file = out / "timed.json";
  std::ofstream(file) << scene.dump();
  const auto stepsOf = [&](const std::string& options, const fs::path& folder) {
    const auto r = runCamcov("run " + file.string() + " --method local " + options + " --out " +
                             folder.string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const auto j = nlohmann::json::parse(readFile(folder / "timed-local-seed1.json"));
    EXPECT_NEAR(j["parameters"]["sim"]["duration"].get<double>(),
                j["summary"]["duration"].get<double>(), 1e-12);
    return j["series"]["time"].size();
  };
  EXPECT_EQ(stepsOf("", out / "own"), 16u);  // 1.5 s in steps of 0.1 s, and t = 0
  EXPECT_EQ(stepsOf("--duration 0.7", out / "asked"), 8u);
  EXPECT_EQ(stepsOf("--set sim.duration=0.9", out / "set"), 10u);

  const fs::path bench = out / "bench";
  const std::string args = "bench --scenes " + file.string() + " " + kScene +
                           " --methods local --seeds 1 --videos none --explorer none "
                           "--optimum-budget 0 --no-report --out " +
                           bench.string();
  ASSERT_EQ(runCamcov(args).exitCode, 0);
  const auto timed = nlohmann::json::parse(readFile(bench / "runs" / "timed-local-seed1.json"));
  const auto plain =
      nlohmann::json::parse(readFile(bench / "runs" / "fig1_example-local-seed1.json"));
  EXPECT_EQ(timed["summary"]["duration"], 1.5);
  EXPECT_EQ(plain["summary"]["duration"], 30.0);
  // The job's parameters hold the scene's duration, as its results do: a resume redoes nothing.
  const auto stamp = fs::last_write_time(bench / "runs" / "timed-local-seed1.json");
  const auto again = runCamcov(args);
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_NE(again.err.find("already done"), std::string::npos) << again.err;
  EXPECT_EQ(fs::last_write_time(bench / "runs" / "timed-local-seed1.json"), stamp);
}

TEST(CliRun, SameArgumentsGiveByteIdenticalFilesAndAnotherSeedDiffers) {
  const fs::path a = freshDir("a"), b = freshDir("b"), c = freshDir("c");
  const std::string args = " --method paper --duration 6 --set global.K=60 --set planner.T2=0.1 ";
  ASSERT_EQ(runCamcov("run " + kScene + args + "--seed 1 --out " + a.string()).exitCode, 0);
  ASSERT_EQ(runCamcov("run " + kScene + args + "--seed 1 --out " + b.string()).exitCode, 0);
  ASSERT_EQ(runCamcov("run " + kScene + args + "--seed 2 --out " + c.string()).exitCode, 0);
  const std::string stem = "fig1_example-paper-seed";
  EXPECT_EQ(readFile(a / (stem + "1.json")), readFile(b / (stem + "1.json")));
  EXPECT_EQ(readFile(a / (stem + "1.csv")), readFile(b / (stem + "1.csv")));
  const auto one = nlohmann::json::parse(readFile(a / (stem + "1.json")));
  const auto two = nlohmann::json::parse(readFile(c / (stem + "2.json")));
  EXPECT_NE(one["series"]["cameras"], two["series"]["cameras"]) << "the method samples";
  EXPECT_FALSE(one["events"].empty());
  EXPECT_EQ(one["events"][0]["kind"], "global");
}

TEST(CliRun, MoreThreadsGiveTheSameBytes) {
  // One thread, three, and by default every core it may run on.
  const fs::path one = freshDir("threads1"), three = freshDir("threads3"),
                 cores = freshDir("threadsCores");
  const std::string args = " --method paper --duration 6 --seed 4 --set global.T1=2 ";
  ASSERT_EQ(runCamcov("run " + kScene + args + "--threads 1 --out " + one.string()).exitCode, 0);
  ASSERT_EQ(runCamcov("run " + kScene + args + "--threads 3 --out " + three.string()).exitCode, 0);
  ASSERT_EQ(runCamcov("run " + kScene + args + "--out " + cores.string()).exitCode, 0);
  const std::string stem = "fig1_example-paper-seed4";
  for (const fs::path& other : {three, cores}) {
    EXPECT_EQ(readFile(one / (stem + ".json")), readFile(other / (stem + ".json")));
    EXPECT_EQ(readFile(one / (stem + ".csv")), readFile(other / (stem + ".csv")));
  }
  EXPECT_EQ(runCamcov("run " + kScene + " --threads 257 --out " + one.string()).exitCode, 2);
}

TEST(CliRun, BadInputExitsTwo) {
  const fs::path out = freshDir("bad") / "out";
  EXPECT_EQ(runCamcov("run " + kScene + " --method magic --out " + out.string()).exitCode, 2);
  EXPECT_EQ(runCamcov("run /nonexistent.json --out " + out.string()).exitCode, 2);
  EXPECT_EQ(runCamcov("run " + kScene + " --set global.K=0 --out " + out.string()).exitCode, 2);
  EXPECT_EQ(runCamcov("run " + kScene + " --duration 1 --out /proc/nope").exitCode, 2);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace camcov::testing
