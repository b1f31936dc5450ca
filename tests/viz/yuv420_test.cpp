// toYuv420 against the BT.709 formulas in floating point, the slow and obvious reference.
#include "viz/yuv420.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace camcov::viz {
namespace {

struct Rgb8 {
  int r, g, b;
};

// Limited-range BT.709 of a full-range colour, unrounded.
double lumaOf(double r, double g, double b) {
  return 16.0 + 219.0 / 255.0 * (0.2126 * r + 0.7152 * g + 0.0722 * b);
}
double cbOf(double r, double g, double b) {
  return 128.0 + 224.0 / 255.0 * (b - (0.2126 * r + 0.7152 * g + 0.0722 * b)) / 1.8556;
}
double crOf(double r, double g, double b) {
  return 128.0 + 224.0 / 255.0 * (r - (0.2126 * r + 0.7152 * g + 0.0722 * b)) / 1.5748;
}

// A width × height ARGB32 image (opaque) with stride padding, and its converted planes.
struct Converted {
  Converted(int width, int height, const std::vector<Rgb8>& pixels) : w(width), h(height) {
    const int stride = 4 * width + 16;
    argb.assign(static_cast<std::size_t>(stride) * height, 0);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const Rgb8 c = pixels[y * width + x];
        const std::uint32_t word = 0xff000000u | (c.r << 16) | (c.g << 8) | c.b;
        std::memcpy(&argb[y * stride + 4 * x], &word, 4);
      }
    }
    luma.assign(width * height, 0);
    cb.assign(width * height / 4, 0);
    cr.assign(width * height / 4, 0);
    toYuv420({argb.data(), width, height, stride},
             {luma.data(), cb.data(), cr.data(), width, width / 2, width / 2});
  }
  int w, h;
  std::vector<std::uint8_t> argb, luma, cb, cr;
};

TEST(Yuv420, BlackAndWhiteAreTheEndsOfTheLimitedRange) {
  const Converted black(2, 2, std::vector<Rgb8>(4, {0, 0, 0}));
  const Converted white(2, 2, std::vector<Rgb8>(4, {255, 255, 255}));
  EXPECT_EQ(black.luma, (std::vector<std::uint8_t>{16, 16, 16, 16}));
  EXPECT_EQ(white.luma, (std::vector<std::uint8_t>{235, 235, 235, 235}));
  for (const Converted* c : {&black, &white}) {
    EXPECT_EQ(c->cb[0], 128);
    EXPECT_EQ(c->cr[0], 128);
  }
}

TEST(Yuv420, EveryPixelAndBlockIsWithinOneOfTheFormula) {
  constexpr int kWidth = 64, kHeight = 32;
  std::mt19937 random(7);
  std::uniform_int_distribution<int> channel(0, 255);
  std::vector<Rgb8> pixels(kWidth * kHeight);
  for (Rgb8& p : pixels)
    p = {channel(random), channel(random), channel(random)};
  pixels[0] = {255, 0, 0};  // saturated primaries, where the weights are at their extremes
  pixels[1] = {0, 255, 0};
  pixels[2] = {0, 0, 255};
  const Converted c(kWidth, kHeight, pixels);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const Rgb8 p = pixels[y * kWidth + x];
      EXPECT_NEAR(c.luma[y * kWidth + x], lumaOf(p.r, p.g, p.b), 1.0) << x << "," << y;
    }
  }
  for (int y = 0; y < kHeight / 2; ++y) {
    for (int x = 0; x < kWidth / 2; ++x) {
      double r = 0.0, g = 0.0, b = 0.0;
      for (const int dy : {0, 1}) {
        for (const int dx : {0, 1}) {
          const Rgb8 p = pixels[(2 * y + dy) * kWidth + 2 * x + dx];
          r += p.r / 4.0;
          g += p.g / 4.0;
          b += p.b / 4.0;
        }
      }
      EXPECT_NEAR(c.cb[y * kWidth / 2 + x], cbOf(r, g, b), 1.0) << x << "," << y;
      EXPECT_NEAR(c.cr[y * kWidth / 2 + x], crOf(r, g, b), 1.0) << x << "," << y;
    }
  }
}

}  // namespace
}  // namespace camcov::viz
