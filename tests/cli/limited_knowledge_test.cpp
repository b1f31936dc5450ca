// Limited knowledge from the command line (docs/method.md, "What a camera knows"): a scene's
// own "knowledge" and "comms" keys, --set over them, the record's message counts, and bad
// settings as bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "support/run_camcov.h"
#include "support/scratch.h"
#include "support/test_paths.h"

namespace camcov::testing {
namespace {

namespace fs = std::filesystem;

// fig1_example with `settings` added at its top level, written into `dir`.
fs::path withSettings(const fs::path& dir, const nlohmann::json& settings) {
  nlohmann::json scene = nlohmann::json::parse(readFile(ownScenesDir() / "fig1_example.json"));
  scene.update(settings);
  const fs::path file = dir / "knowing.json";
  std::ofstream(file) << scene.dump(2);
  return file;
}

nlohmann::json runOf(const fs::path& scene, const fs::path& out, const std::string& extra = "") {
  const auto r = runCamcov("run " + scene.string() + " --method local --seed 1 --duration 3 " +
                           extra + " --out " + out.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return nlohmann::json::parse(readFile(out / "knowing-local-seed1.json"));
}

TEST(LimitedKnowledgeCli, AScenesSettingsReachTheRunAndItsRecordCountsTheMessages) {
  const ScratchDir dir;
  const fs::path scene = withSettings(dir.path(), {{"knowledge", {{"limited", true}}},
                                                   {"comms", {{"range", "inf"}, {"loss", 0.5}}}});
  const nlohmann::json run = runOf(scene, dir / "a");
  EXPECT_EQ(run["parameters"]["knowledge"]["limited"], true);
  EXPECT_EQ(run["parameters"]["comms"]["range"], "inf");
  EXPECT_EQ(run["parameters"]["comms"]["loss"], 0.5);
  const auto& messages = run["summary"]["messages"];
  const int sent = messages["sent"], delivered = messages["delivered"], lost = messages["lost"];
  EXPECT_EQ(sent, delivered + lost);
  EXPECT_GT(lost, 0);
  EXPECT_GT(delivered, 0);
  // --set says otherwise than the scene.
  const nlohmann::json lossless = runOf(scene, dir / "b", "--set comms.loss=0.25");
  EXPECT_EQ(lossless["parameters"]["comms"]["loss"], 0.25);
}

TEST(LimitedKnowledgeCli, ARunWithoutItHasNoMessagesAndNoKnowledgeParameters) {
  const ScratchDir dir;
  const fs::path scene = withSettings(dir.path(), nlohmann::json::object());
  const nlohmann::json run = runOf(scene, dir / "a", "--set comms.range=5");
  EXPECT_FALSE(run["summary"].contains("messages"));
  EXPECT_FALSE(run["parameters"].contains("knowledge"));
  EXPECT_FALSE(run["parameters"].contains("comms"));
}

TEST(LimitedKnowledgeCli, SettingsOutsideTheirRangeExitTwoNamingFileAndKey) {
  const ScratchDir dir;
  const fs::path scene = withSettings(dir.path(), {{"comms", {{"loss", 2}}}});
  const std::string expected = scene.string() + ": comms.loss = 2 is outside [0, 1]";
  const auto validate = runCamcov("validate " + scene.string());
  EXPECT_EQ(validate.exitCode, 2);
  EXPECT_NE(validate.out.find("error " + expected), std::string::npos) << validate.out;
  const auto run = runCamcov("run " + scene.string() + " --out " + (dir / "a").string());
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_NE(run.err.find(expected), std::string::npos) << run.err;
  const auto set = runCamcov("run " + scene.string() + " --set comms.range=-1");
  EXPECT_EQ(set.exitCode, 2);
}

}  // namespace
}  // namespace camcov::testing
