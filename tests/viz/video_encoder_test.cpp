#include "viz/video_encoder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "viz/frame.h"
#include "viz/frame_renderer.h"
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

// Red, green, blue and white quadrants come back from a decoder as their BT.709
// limited-range values (published: red 63/102/240, green 173/42/26, blue 32/240/118, white
// 235/128/128), give or take what the lossy coding moves in the middle of a flat area.
TEST(VideoEncoder, DecodesToTheBt709ValuesOfTheColoursDrawn) {
  constexpr int kWidth = 64, kHeight = 48;
  struct Quadrant {
    std::uint32_t argb;
    int y, u, v;
  };
  const Quadrant quadrants[] = {{0xffff0000u, 63, 102, 240},  // top left
                                {0xff00ff00u, 173, 42, 26},   // top right
                                {0xff0000ffu, 32, 240, 118},  // bottom left
                                {0xffffffffu, 235, 128, 128}};
  const auto quadrantOf = [&](int x, int y) {
    return quadrants[(y < kHeight / 2 ? 0 : 2) + (x < kWidth / 2 ? 0 : 1)];
  };
  std::vector<std::uint32_t> pixels(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x)
      pixels[y * kWidth + x] = quadrantOf(x, y).argb;
  }
  ScratchDir dir;
  VideoEncoder encoder(dir / "quadrants.mp4", small(10));
  encoder.addFrame(
      {reinterpret_cast<const std::uint8_t*>(pixels.data()), kWidth, kHeight, 4 * kWidth});
  encoder.finish();

  const std::string yuv = testing::firstFrameYuv420(dir / "quadrants.mp4");
  ASSERT_EQ(yuv.size(), std::size_t{kWidth * kHeight * 3 / 2});
  const auto sample = [&](std::size_t offset) { return static_cast<unsigned char>(yuv[offset]); };
  constexpr std::size_t kU = kWidth * kHeight, kV = kU + kWidth * kHeight / 4;
  for (const int y : {kHeight / 4, 3 * kHeight / 4}) {
    for (const int x : {kWidth / 4, 3 * kWidth / 4}) {
      const Quadrant& q = quadrantOf(x, y);
      const std::size_t chroma = y / 2 * (kWidth / 2) + x / 2;
      EXPECT_NEAR(sample(y * kWidth + x), q.y, 2) << x << "," << y;
      EXPECT_NEAR(sample(kU + chroma), q.u, 2) << x << "," << y;
      EXPECT_NEAR(sample(kV + chroma), q.v, 2) << x << "," << y;
    }
  }
}

// The encoder converts only the areas an image says changed since the one it converted last
// (RasterImage::changedSince), and nothing for a frame held over. The video must be byte for
// byte the one made from the same pixels converted whole: frames of a moving camera, one
// held for two frames, and one whose still part changes (the caption's time changes in
// every frame, so a stale caption row would show), and one drawn but left out.
TEST(VideoEncoder, ConvertingOnlyWhatChangedGivesTheSameVideo) {
  const scene::Scene scene = scene::loadScene(testing::tinyScene());
  FrameBuilder builder(scene);
  VideoSettings settings = small(10);
  settings.width = 320;
  settings.height = 240;
  FrameRenderer renderer(settings.width, settings.height, FrameUse::Video);
  ScratchDir dir;
  VideoEncoder partly(dir / "partly.mp4", settings), wholly(dir / "wholly.mp4", settings);
  Frame frame;
  int changedOnly = 0;
  for (int k = 0; k < 12; ++k) {
    const double t = 0.1 * k;
    builder.build(t, std::vector<geometry::Pose>{{-3.0 + 0.2 * k, 0.1 * k, 0.15 * k}}, frame);
    frame.caption.subtitle = k < 8 ? "first" : "second";
    const RasterImage image = renderer.rasterize(frame);
    changedOnly += image.changedSince != 0;
    if (k == 8) continue;  // drawn, not encoded: the next image changed since one not seen
    for (int held = 0; held < (k == 5 ? 2 : 1); ++held) {
      partly.addFrame(image);
      wholly.addFrame({image.pixels, image.width, image.height, image.stride});
    }
  }
  partly.finish();
  wholly.finish();
  EXPECT_EQ(changedOnly, 10);  // all but the first frame and the one with a new subtitle
  const std::string video = testing::readFile(dir / "partly.mp4");
  ASSERT_FALSE(video.empty());
  EXPECT_EQ(video, testing::readFile(dir / "wholly.mp4"));
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
