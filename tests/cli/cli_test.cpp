// End-to-end: the camcov executable as a user runs it.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "camcov/version.h"
#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

TEST(Cli, PrintsVersion) {
  const auto r = runCamcov("--version");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find(kVersion), std::string::npos);
}

TEST(Cli, EverySubcommandHasHelp) {
  for (const char* sub : {"validate", "state", "params", "inspect", "run"}) {
    const auto r = runCamcov(std::string(sub) + " --help");
    EXPECT_EQ(r.exitCode, 0) << sub;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub << ": " << r.out;
  }
  EXPECT_EQ(runCamcov("--help").exitCode, 0);
}

TEST(Cli, UsageErrorsExitWithTwo) {
  EXPECT_EQ(runCamcov("").exitCode, 2);                     // no subcommand
  EXPECT_EQ(runCamcov("frobnicate").exitCode, 2);           // unknown subcommand
  EXPECT_EQ(runCamcov("state").exitCode, 2);                // missing file
  EXPECT_EQ(runCamcov("params --set nope=1").exitCode, 2);  // unknown parameter
}

TEST(CliValidate, AcceptsEveryPublishedAndOwnScene) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  std::string args = "validate";
  for (const auto& dir : {publishedScenesDir(), ownScenesDir()}) {
    for (const auto& f : jsonFilesIn(dir))
      args.append(" ").append(f.string());
  }
  const auto r = runCamcov(args);
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("error"), std::string::npos) << r.out;
}

TEST(CliValidate, EveryBadFileExitsTwoNamingTheFile) {
  for (const auto& f : jsonFilesIn(testDataDir() / "bad")) {
    const auto r = runCamcov("validate " + f.string());
    EXPECT_EQ(r.exitCode, 2) << f;
    const std::string expected = "error " + f.string();  // then ": " and the JSON path
    EXPECT_NE(r.out.find(expected + ": "), std::string::npos) << r.out;
  }
}

TEST(CliValidate, OneBadFileAmongGoodOnesStillFailsAndReportsEach) {
  const auto good = ownScenesDir() / "fig1_example.json";
  const auto bad = testDataDir() / "bad" / "no_cameras.json";
  const auto r = runCamcov("validate " + good.string() + " " + bad.string());
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.out.find("ok    " + good.string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("error " + bad.string()), std::string::npos) << r.out;
}

TEST(CliValidate, ObjectsThatPassThroughEachOtherAreAWarningInValidateAndTheReport) {
  const auto file = testDataDir() / "warnings" / "target_through_obstacle.json";
  const auto r = runCamcov("validate " + file.string());
  EXPECT_EQ(r.exitCode, 0) << r.out;
  const std::string warning =
      "targets[0] and obstacles[0] pass through each other at t = 1.1 s near (-0.95, 0.00)";
  EXPECT_NE(r.out.find("  warning: " + warning + " (checked every 0.1 s over 30 s)"),
            std::string::npos)
      << r.out;
  // The report says so under the scene, over the batch's own duration.
  const ScratchDir dir;
  const auto bench = runCamcov("bench --scenes " + file.string() +
                               " --methods local --seeds 1 --duration 2 --videos none "
                               "--explorer none --optimum-budget 0 --out " +
                               (dir / "b").string());
  ASSERT_EQ(bench.exitCode, 0) << bench.out << bench.err;
  EXPECT_NE(readFile(dir / "b" / "report.html")
                .find("<p class=\"note scene-warning\">warning: " + warning + "</p>"),
            std::string::npos);
  ASSERT_EQ(runCamcov("bench --scenes " + file.string() +
                      " --methods local --seeds 1 --duration 1 --videos none --explorer none "
                      "--optimum-budget 0 --out " +
                      (dir / "short").string())
                .exitCode,
            0);
  EXPECT_EQ(readFile(dir / "short" / "report.html").find("class=\"note scene-warning\""),
            std::string::npos)
      << "a run that ends before they meet has nothing to warn of";
}

// A scene with its own length (an imported window: 9.7 s as a difference of recorded times) is
// checked over that length, and every length printed reads as written.
TEST(CliValidate, OverlapsAreCheckedOverTheScenesOwnDurationPrintedRounded) {
  auto scene =
      nlohmann::json::parse(readFile(testDataDir() / "warnings" / "target_through_obstacle.json"));
  scene["duration"] = 12.3 - 2.6;  // 9.700000000000001
  const ScratchDir dir;
  const auto file = dir / "window.json";
  std::ofstream(file) << scene.dump();
  const auto validated = runCamcov("validate " + file.string());
  EXPECT_EQ(validated.exitCode, 0) << validated.out;
  EXPECT_NE(validated.out.find("(checked every 0.1 s over 9.7 s)"), std::string::npos)
      << validated.out;
  const auto ran =
      runCamcov("run " + file.string() + " --method local --out " + dir.path().string());
  ASSERT_EQ(ran.exitCode, 0) << ran.out << ran.err;
  EXPECT_NE(ran.out.find(" over 9.7 s;"), std::string::npos) << ran.out;
}

TEST(CliState, Dynamic9AtSevenPointThreeFollowsTheLoopRule) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const auto r =
      runCamcov("state " + (publishedScenesDir() / "dynamic9.json").string() + " --time 7.3");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scene"], "dynamic9");
  EXPECT_EQ(j["targets"].size(), 6u);
  EXPECT_EQ(j["cameras"].size(), 5u);
  // Target 0 goes (0 5) -> (0 -5) at 0.5 m/s: 3.65 m down after 7.3 s.
  EXPECT_NEAR(j["targets"][0]["reference"][1].get<double>(), 1.35, 1e-12);
  // Polygon vertices are the shape about the reference; first vertex (-1, 0) of the shape.
  const auto& poly = j["targets"][0]["polygon"];
  double twiceArea = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const auto& a = poly[i];
    const auto& b = poly[(i + 1) % poly.size()];
    twiceArea += a[0].get<double>() * b[1].get<double>() - b[0].get<double>() * a[1].get<double>();
  }
  EXPECT_GT(twiceArea, 0.0) << "rings are counter-clockwise";
  EXPECT_NE(poly[0], poly[poly.size() - 1]) << "rings are open";
}

TEST(CliState, MissingSceneFileExitsTwo) {
  const auto r = runCamcov("state /nonexistent.json --time 1");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/nonexistent.json"), std::string::npos) << r.err;
}

TEST(CliParams, PrintsDefaultsAndAppliesOverridesInOrder) {
  auto r = runCamcov("params --set global.K=50 --set global.K=60 --set planner.T2=0.25");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["global"]["K"], 60);
  EXPECT_EQ(j["planner"]["T2"], 0.25);
  EXPECT_EQ(j["reward"]["lambda2"], 0.2);
  r = runCamcov("params --describe");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("λ1"), std::string::npos);
}

}  // namespace
}  // namespace camcov::testing
