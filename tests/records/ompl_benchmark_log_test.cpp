// The OMPL benchmark logs of a batch folder: one per scene, the same bytes whether one worker
// or several read the run files back, and a broken run file reported as one worker meets it.
#include "records/ompl_benchmark_log.h"

#include <gtest/gtest.h>

#include <fstream>

#include "records/run_files.h"
#include "support/scratch.h"

namespace camcov::records {
namespace {

namespace fs = std::filesystem;

// A run of `scene` by `method` with `seed`, whose coverage tells them apart.
RunRecord runOf(const std::string& scene, const std::string& method, std::uint64_t seed) {
  RunRecord run;
  run.metadata = {scene, "scenes/" + scene + ".json", 0x42, method, seed, {}, "9.9.9"};
  run.summary.steps = 3;
  run.summary.duration = 0.3;
  const double coverage = 0.125 * static_cast<double>(seed) + (method == "paper" ? 0.5 : 0.0);
  run.summary.averageCoverage = coverage;
  run.summary.averageUtilization = 0.5;
  for (int k = 0; k < 3; ++k) {
    StepRow row;
    row.time = 0.1 * k;
    row.terms.coverage = row.terms.weightedCoverage = coverage;
    row.terms.utilization = 0.5;
    row.cameras = {{1.0, 2.0, 0.5}};
    row.goals = {std::nullopt};
    run.steps.push_back(row);
  }
  return run;
}

// The manifest of batchWithRuns's batch.
BatchManifest manifestOfTwoMethods() {
  BatchManifest manifest;
  manifest.methods = {"paper", "local"};
  return manifest;
}

// The batch folder `dir` with seven scenes, two methods and three seeds each.
BatchFolder batchWithRuns(const fs::path& dir) {
  const BatchFolder folder(dir);
  fs::create_directories(folder.runsDir());
  for (int s = 0; s < 7; ++s) {
    for (const char* method : {"paper", "local"}) {
      for (std::uint64_t seed = 1; seed <= 3; ++seed)
        writeRunFiles(runOf("scene_" + std::to_string(s), method, seed), folder.runsDir());
    }
  }
  return folder;
}

TEST(OmplBenchmarkLogs, AreTheSameBytesWhateverTheNumberOfWorkers) {
  const BatchFolder one = batchWithRuns(testing::freshDir("one"));
  const BatchFolder three = batchWithRuns(testing::freshDir("three"));
  const auto fromOne = writeOmplBenchmarkLogs(one, manifestOfTwoMethods(), 1);
  const auto fromThree = writeOmplBenchmarkLogs(three, manifestOfTwoMethods(), 3);
  ASSERT_EQ(fromOne.size(), 7u);
  ASSERT_EQ(fromThree.size(), 7u);
  for (std::size_t i = 0; i < fromOne.size(); ++i) {
    EXPECT_EQ(fromOne[i].filename(), fromThree[i].filename());
    EXPECT_EQ(fromOne[i].filename(), "scene_" + std::to_string(i) + ".log");
    const std::string text = testing::readFile(fromOne[i]);
    EXPECT_NE(text.find("2 planners"), std::string::npos);
    EXPECT_EQ(text, testing::readFile(fromThree[i]));
  }
}

// The runs a batch kept in memory give the logs that reading every run file back gives, to the
// byte; a kept run is taken from memory (its file is not read: here it is broken).
TEST(OmplBenchmarkLogs, RunsKeptInMemoryGiveTheBytesOfRunsReadBack) {
  const BatchFolder readBack = batchWithRuns(testing::freshDir("read_back"));
  const BatchFolder fromMemory = batchWithRuns(testing::freshDir("from_memory"));
  std::map<std::string, OmplRun> kept;
  for (int s = 0; s < 7; s += 2) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      const RunRecord run = runOf("scene_" + std::to_string(s), "paper", seed);
      kept.emplace(runStem(run.metadata), omplRunOf(run));
      std::ofstream(fromMemory.runFile(runStem(run.metadata))) << "{ broken";
    }
  }
  const auto expected = writeOmplBenchmarkLogs(readBack, manifestOfTwoMethods(), 2);
  const auto logs = writeOmplBenchmarkLogs(fromMemory, manifestOfTwoMethods(), 2, kept);
  ASSERT_EQ(logs.size(), expected.size());
  for (std::size_t i = 0; i < logs.size(); ++i) {
    EXPECT_EQ(logs[i].filename(), expected[i].filename());
    EXPECT_EQ(testing::readFile(logs[i]), testing::readFile(expected[i])) << logs[i];
  }
}

TEST(OmplBenchmarkLogs, ABrokenRunFileIsReportedAsOneWorkerMeetsIt) {
  for (const unsigned workers : {1u, 4u}) {
    SCOPED_TRACE(workers);
    const BatchFolder folder = batchWithRuns(testing::freshDir("broken"));
    for (const char* stem : {"scene_2-local-seed2", "scene_5-paper-seed1"})
      std::ofstream(folder.runFile(stem)) << "{ not json";
    try {
      writeOmplBenchmarkLogs(folder, manifestOfTwoMethods(), workers);
      ADD_FAILURE() << "no error";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find("scene_2-local-seed2"), std::string::npos) << e.what();
    }
  }
}

// Method names may hold dashes: camcov-dec's runs of scene "a" are "a-camcov-dec-seed1", which
// must not be taken for scene "a-camcov"'s runs of a method "dec"; and a method whose results an
// earlier batch left in the folder (its identity kept in the manifest) is one of the scene's.
TEST(OmplBenchmarkLogs, RunsAreGroupedBySceneWhateverDashesTheirMethodsAndScenesHold) {
  const BatchFolder folder(testing::freshDir("dashes"));
  fs::create_directories(folder.runsDir());
  for (const char* scene : {"a", "a-camcov", "hall-2"}) {
    for (const char* method : {"camcov", "camcov-dec", "paper"})
      writeRunFiles(runOf(scene, method, 1), folder.runsDir());
  }
  BatchManifest manifest;
  manifest.methods = {"camcov-dec", "camcov"};
  manifest.methodIdentities = {{"paper", "c++ 0123"}};
  const auto logs = writeOmplBenchmarkLogs(folder, manifest, 2);
  ASSERT_EQ(logs.size(), 3u);
  EXPECT_EQ(logs[0].filename(), "a.log");
  EXPECT_EQ(logs[1].filename(), "a-camcov.log");
  EXPECT_EQ(logs[2].filename(), "hall-2.log");
  for (const auto& log : logs) {
    const std::string text = testing::readFile(log);
    EXPECT_NE(text.find("3 planners\ncamcov\n"), std::string::npos) << text.substr(0, 600);
    EXPECT_NE(text.find("\ncamcov-dec\n"), std::string::npos);
    EXPECT_NE(text.find("\npaper\n"), std::string::npos);
  }
}

TEST(SceneOfStem, TakesTheLongestMethodThatEndsTheStem) {
  const std::vector<std::string> methods{"camcov", "camcov-dec", "paper"};
  EXPECT_EQ(sceneOfStem("a-camcov-dec-seed12", methods), "a");
  EXPECT_EQ(sceneOfStem("a-camcov-seed1", methods), "a");
  EXPECT_EQ(sceneOfStem("a-camcov-camcov-dec-seed1", methods), "a-camcov");
  EXPECT_EQ(sceneOfStem("x-paper-seed3", methods), "x");
  EXPECT_EQ(sceneOfStem("x-local-seed3", methods), std::nullopt) << "a method not listed";
  EXPECT_EQ(sceneOfStem("paper-seed3", methods), std::nullopt) << "no scene";
  EXPECT_EQ(sceneOfStem("x-paper-seed", methods), std::nullopt) << "no seed";
  EXPECT_EQ(sceneOfStem("x-paper-seed1b", methods), std::nullopt);
}

}  // namespace
}  // namespace camcov::records
