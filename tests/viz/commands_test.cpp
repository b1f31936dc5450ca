// End-to-end: camcov render, camcov video, camcov run --video and camcov inspect -o (the sweep
// debugger) as a user runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/run_camcov.h"
#include "viz_test_support.h"

namespace camcov::testing {
namespace {

std::string quoted(const std::filesystem::path& p) {
  // Appended, not "'" + ...: GCC 12 warns falsely (-Wrestrict) on the latter.
  std::string s(1, '\'');
  s.append(p.string()).push_back('\'');
  return s;
}

std::string head(const std::filesystem::path& file, std::size_t n) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  return bytes;
}

TEST(RenderCommand, WritesPngOrSvgByExtension) {
  ScratchDir dir;
  for (const char* name : {"f.png", "f.svg"}) {
    const auto r = runCamcov("render " + quoted(tinyScene()) +
                             " --time 1 --width 640 --height 360 -o " + quoted(dir / name));
    EXPECT_EQ(r.exitCode, 0) << r.err;
  }
  EXPECT_EQ(head(dir / "f.png", 8), "\x89PNG\r\n\x1a\n");
  EXPECT_NE(head(dir / "f.svg", 200).find("<svg"), std::string::npos);
}

// As inspect -o and the results files: the folder is made, and the file appears whole.
TEST(RenderCommand, CreatesTheFolderAndLeavesOnlyTheImage) {
  ScratchDir dir;
  const auto png = dir / "frames" / "t1" / "f.png";
  const auto r = runCamcov("render " + quoted(tinyScene()) + " --time 1 -o " + quoted(png));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(head(png, 8), "\x89PNG\r\n\x1a\n");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(png.parent_path()))
    ++files;
  EXPECT_EQ(files, 1u);
}

// A 3 s run at dt = 0.1 s records 31 steps: 31 frames at 10 fps, 3.1 s.
TEST(RunCommand, VideoOptionWritesBrowserPlayableMp4OfTheRun) {
  ScratchDir dir;
  const auto video = dir / "run.mp4";
  const auto r = runCamcov("run " + quoted(tinyScene()) + " --method local --duration 3 --out " +
                           quoted(dir / "results") + " --video " + quoted(video));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto facts = probeVideo(video);
  EXPECT_EQ(facts.codec, "h264");
  EXPECT_EQ(facts.pixelFormat, "yuv420p");
  EXPECT_EQ(facts.width, 1280);
  EXPECT_EQ(facts.height, 720);
  EXPECT_EQ(facts.frames, 31);
  EXPECT_NEAR(facts.duration, 3.1, 1e-3);
  const auto boxes = topLevelBoxes(video);
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  EXPECT_LT(moov, std::find(boxes.begin(), boxes.end(), "mdat"));  // +faststart
}

class RecordedRun : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto r = runCamcov("run " + quoted(tinyScene()) + " --method local --duration 2 --out " +
                             quoted(dir_ / "results"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    results_ = dir_ / "results" / "tiny_scene-local-seed1.json";
    ASSERT_TRUE(std::filesystem::exists(results_));
  }
  ScratchDir dir_;
  std::filesystem::path results_;
};

TEST_F(RecordedRun, VideoResamplesToTheRequestedRate) {
  const auto video = dir_ / "v.mp4";
  const auto r = runCamcov("video " + quoted(results_) + " -o " + quoted(video) +
                           " --fps 25 --width 320 --height 180");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto facts = probeVideo(video);
  EXPECT_EQ(facts.frames, 51);  // 2 s at 25 fps, both ends included
  EXPECT_EQ(facts.width, 320);
  EXPECT_NEAR(facts.duration, 51.0 / 25.0, 1e-3);
}

TEST_F(RecordedRun, MovedSceneIsFoundThroughTheSceneOption) {
  auto run = nlohmann::json::parse(std::ifstream(results_));
  run["scene"]["file"] = (dir_ / "gone.json").string();
  const auto moved = dir_ / "moved.json";
  std::ofstream(moved) << run.dump();
  const auto video = dir_ / "v.mp4";
  const auto lost = runCamcov("video " + quoted(moved) + " -o " + quoted(video));
  EXPECT_EQ(lost.exitCode, 2);
  EXPECT_NE(lost.err.find("--scene"), std::string::npos) << lost.err;
  const auto found = runCamcov("video " + quoted(moved) + " -o " + quoted(video) + " --scene " +
                               quoted(tinyScene()));
  EXPECT_EQ(found.exitCode, 0) << found.err;
}

TEST_F(RecordedRun, BadInputsExitTwo) {
  EXPECT_EQ(runCamcov("video " + quoted(dir_ / "missing.json") + " -o " + quoted(dir_ / "v.mp4"))
                .exitCode,
            2);
  EXPECT_EQ(runCamcov("video " + quoted(results_) + " -o " + quoted(dir_ / "v.avi")).exitCode, 2);
  EXPECT_EQ(runCamcov("video " + quoted(results_) + " -o " + quoted(dir_ / "v.mp4") +
                      " --width 321 --height 180")
                .exitCode,
            2);
  EXPECT_EQ(runCamcov("video " + quoted(tinyScene()) + " -o " + quoted(dir_ / "v.mp4")).exitCode,
            2);  // a scene is not a results file
  EXPECT_EQ(runCamcov("render " + quoted(tinyScene()) + " -o " + quoted(dir_ / "f.jpg")).exitCode,
            2);
  std::ofstream(dir_ / "plain") << "not a folder";
  EXPECT_EQ(runCamcov("render " + quoted(tinyScene()) + " -o " + quoted(dir_ / "plain" / "f.png"))
                .exitCode,
            2);
  // Rejected before the simulation runs: no results are written.
  EXPECT_EQ(runCamcov("run " + quoted(tinyScene()) + " --duration 1 --out " +
                      quoted(dir_ / "other") + " --video " + quoted(dir_ / "v.avi"))
                .exitCode,
            2);
  EXPECT_FALSE(std::filesystem::exists(dir_ / "other"));
}

TEST(InspectCommand, OutOptionWritesTheSweepOfTheChosenCameraBesideTheUsualAnswer) {
  ScratchDir dir;
  const auto svg = dir / "debug.svg";
  const auto r =
      runCamcov("inspect " + quoted(tinyScene()) + " --time 0 --camera 0 --json -o " + quoted(svg));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // --json output stays pure JSON
  EXPECT_EQ(j["cameras"].size(), 1u);
  std::stringstream contents;
  contents << std::ifstream(svg).rdbuf();
  const std::string text = contents.str();
  EXPECT_EQ(text.rfind("<?xml", 0), 0u);
  EXPECT_NE(text.find("the sweep of camera 0"), std::string::npos);
  EXPECT_NE(text.find(">e1 "), std::string::npos);   // the table's first row
  EXPECT_NE(text.find(">{0}<"), std::string::npos);  // the seen edge's visibleBy set
  // Written through a temporary file and renamed: nothing else is left in the folder.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir / ""))
    ++files;
  EXPECT_EQ(files, 1u);
}

TEST(InspectCommand, BadOutOptionsExitTwoWithoutWriting) {
  ScratchDir dir;
  const std::string scene = "inspect " + quoted(tinyScene()) + " --time 0 ";
  EXPECT_EQ(runCamcov(scene + "-o " + quoted(dir / "d.png")).exitCode, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "d.png"));
  EXPECT_EQ(runCamcov(scene + "--camera 1 -o " + quoted(dir / "d.svg")).exitCode, 2);  // 1 camera
  EXPECT_EQ(runCamcov(scene + "--camera -1 -o " + quoted(dir / "d.svg")).exitCode, 2);
  EXPECT_EQ(runCamcov(scene + "--camera 0").exitCode, 2);  // nothing to draw it into
  EXPECT_FALSE(std::filesystem::exists(dir / "d.svg"));
  std::ofstream(dir / "file") << "not a folder";
  const auto r = runCamcov(scene + "-o " + quoted(dir / "file" / "d.svg"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("file"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace camcov::testing
