#include "viz/video_encoder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

#include "util/input_error.h"
#include "viz_test_support.h"

namespace camcov::viz {
namespace {

using testing::ScratchDir;

// Opaque ARGB32 frames whose colour changes with k, so no two frames are alike.
class Frames {
 public:
  Frames(int width, int height) : width_(width), height_(height), pixels_(width * height) {}
  RasterImage frame(int k) {
    std::fill(pixels_.begin(), pixels_.end(), 0xff000000u | (k * 40u % 256u) << 16 | 0x8040u);
    return {reinterpret_cast<const std::uint8_t*>(pixels_.data()), width_, height_, 4 * width_};
  }

 private:
  int width_, height_;
  std::vector<std::uint32_t> pixels_;
};

VideoSettings small(int fps) {
  VideoSettings s;
  s.width = 64;
  s.height = 48;
  s.fps = fps;
  return s;
}

TEST(VideoEncoder, WritesH264Yuv420pWithOneFramePerCallAndTheIndexFirst) {
  ScratchDir dir;
  const auto file = dir / "clip.mp4";
  Frames frames(64, 48);
  VideoEncoder encoder(file, small(4));
  for (int k = 0; k < 12; ++k)
    encoder.addFrame(frames.frame(k));
  encoder.finish();
  EXPECT_EQ(encoder.frames(), 12);
  EXPECT_FALSE(std::filesystem::exists(dir / "clip.mp4.part"));

  const auto facts = testing::probeVideo(file);
  EXPECT_EQ(facts.codec, "h264");
  EXPECT_EQ(facts.pixelFormat, "yuv420p");
  EXPECT_EQ(facts.width, 64);
  EXPECT_EQ(facts.height, 48);
  EXPECT_EQ(facts.frames, 12);
  EXPECT_NEAR(facts.duration, 3.0, 1e-3);  // 12 frames at 4 fps

  // +faststart: the index (moov) precedes the media data (mdat).
  const auto boxes = testing::topLevelBoxes(file);
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  const auto mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  ASSERT_NE(moov, boxes.end());
  ASSERT_NE(mdat, boxes.end());
  EXPECT_LT(moov, mdat);
}

TEST(VideoEncoder, AbandonedVideoLeavesNoFileBehind) {
  ScratchDir dir;
  Frames frames(64, 48);
  {
    VideoEncoder encoder(dir / "clip.mp4", small(10));
    encoder.addFrame(frames.frame(0));
    encoder.addFrame(frames.frame(1));
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "clip.mp4"));
  EXPECT_FALSE(std::filesystem::exists(dir / "clip.mp4.part"));
}

TEST(VideoEncoder, RejectsOddSizesAndFramesOfTheWrongSize) {
  ScratchDir dir;
  VideoSettings odd = small(10);
  odd.width = 65;
  EXPECT_THROW(VideoEncoder(dir / "a.mp4", odd), std::invalid_argument);
  Frames wrong(32, 48);
  VideoEncoder encoder(dir / "b.mp4", small(10));
  EXPECT_THROW(encoder.addFrame(wrong.frame(0)), std::invalid_argument);
}

TEST(VideoEncoder, OtherExtensionsAndUnwritablePlacesAreInputErrors) {
  EXPECT_THROW(requireMp4("run.avi"), InputError);
  EXPECT_NO_THROW(requireMp4("run.MP4"));
  ScratchDir dir;
  std::ofstream(dir / "plain") << "not a folder";
  EXPECT_THROW(VideoEncoder(dir / "plain" / "run.mp4", small(10)), InputError);
}

TEST(VideoEncoder, MakesTheFoldersOfItsFile) {
  ScratchDir dir;
  const auto file = dir / "videos" / "new" / "run.mp4";
  Frames frames(64, 48);
  VideoEncoder encoder(file, small(10));
  encoder.addFrame(frames.frame(0));
  encoder.finish();
  EXPECT_TRUE(std::filesystem::is_regular_file(file));
}

}  // namespace
}  // namespace camcov::viz
