// argbToYuv420 against two independent references: the BT.709 limited-range formulas in
// double precision (every sample within half a level, plus the fixed point's 0.02), and
// libswscale's conversion with exact 2×2 chroma averaging (within one level). Widths that are
// not multiples of eight take the plain path for their last columns, so both paths are
// checked.
#include "viz/argb_to_yuv420.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

extern "C" {
#include <libswscale/swscale.h>
}

namespace camcov::viz {
namespace {

constexpr double kKr = 0.2126, kKb = 0.0722, kKg = 1.0 - kKr - kKb;

// An opaque ARGB32 image with `pad` spare bytes at the end of each row.
class Image {
 public:
  Image(int width, int height, int pad = 0)
      : width_(width), height_(height), stride_(4 * width + pad), bytes_(stride_ * height) {}

  void set(int x, int y, int r, int g, int b) {
    const std::uint32_t word = 0xff000000u | r << 16 | g << 8 | b;
    std::memcpy(&bytes_[y * stride_ + 4 * x], &word, 4);
  }
  std::uint32_t get(int x, int y) const {
    std::uint32_t word;
    std::memcpy(&word, &bytes_[y * stride_ + 4 * x], 4);
    return word;
  }
  RasterImage raster() const { return {bytes_.data(), width_, height_, stride_}; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  int width_, height_, stride_;
  std::vector<std::uint8_t> bytes_;
};

Image randomImage(int width, int height, std::mt19937& random, int pad = 0) {
  Image image(width, height, pad);
  std::uniform_int_distribution<int> level(0, 255);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      image.set(x, y, level(random), level(random), level(random));
  }
  return image;
}

// The three planes, with rows `pad` bytes longer than they need be.
struct Planes {
  Planes(int width, int height, int pad = 0)
      : width(width),
        height(height),
        strides{width + pad, width / 2 + pad, width / 2 + pad},
        y(strides[0] * height),
        u(strides[1] * height / 2),
        v(strides[2] * height / 2) {}

  Yuv420Picture picture() {
    return {{y.data(), u.data(), v.data()}, {strides[0], strides[1], strides[2]}};
  }
  int lumaAt(int x, int row) const { return y[row * strides[0] + x]; }
  int uAt(int x, int row) const { return u[row * strides[1] + x]; }
  int vAt(int x, int row) const { return v[row * strides[2] + x]; }

  int width, height;
  int strides[3];
  std::vector<std::uint8_t> y, u, v;
};

Planes converted(const Image& image, int pad = 0) {
  Planes planes(image.width(), image.height(), pad);
  argbToYuv420(image.raster(), planes.picture());
  return planes;
}

struct Rgb {
  double r, g, b;
};
Rgb rgbOf(std::uint32_t word) {
  return {static_cast<double>((word >> 16) & 255), static_cast<double>((word >> 8) & 255),
          static_cast<double>(word & 255)};
}
double exactLuma(Rgb c) {
  return 16.0 + 219.0 / 255.0 * (kKr * c.r + kKg * c.g + kKb * c.b);
}
double exactU(Rgb c) {
  const double luma = kKr * c.r + kKg * c.g + kKb * c.b;
  return 128.0 + 224.0 / 255.0 * (c.b - luma) / (2.0 * (1.0 - kKb));
}
double exactV(Rgb c) {
  const double luma = kKr * c.r + kKg * c.g + kKb * c.b;
  return 128.0 + 224.0 / 255.0 * (c.r - luma) / (2.0 * (1.0 - kKr));
}
// The mean colour of the 2×2 block whose top left pixel is (2 cx, 2 cy).
Rgb blockMean(const Image& image, int cx, int cy) {
  Rgb sum{0, 0, 0};
  for (int dy = 0; dy < 2; ++dy) {
    for (int dx = 0; dx < 2; ++dx) {
      const Rgb c = rgbOf(image.get(2 * cx + dx, 2 * cy + dy));
      sum = {sum.r + c.r / 4, sum.g + c.g / 4, sum.b + c.b / 4};
    }
  }
  return sum;
}

TEST(ArgbToYuv420, PrimariesWhiteAndBlackGetTheirBt709LimitedRangeValues) {
  struct Case {
    int r, g, b;
    int y, u, v;  // the published 8-bit BT.709 limited-range values
  };
  const Case cases[] = {{255, 255, 255, 235, 128, 128}, {0, 0, 0, 16, 128, 128},
                        {255, 0, 0, 63, 102, 240},      {0, 255, 0, 173, 42, 26},
                        {0, 0, 255, 32, 240, 118},      {128, 128, 128, 126, 128, 128}};
  for (const Case& c : cases) {
    Image image(18, 4);  // 16 columns on the SSE2 path, 2 on the plain one
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 18; ++x)
        image.set(x, y, c.r, c.g, c.b);
    }
    const Planes out = converted(image);
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 18; ++x)
        ASSERT_EQ(out.lumaAt(x, y), c.y) << c.r << "," << c.g << "," << c.b << " at " << x;
    }
    for (int y = 0; y < 2; ++y) {
      for (int x = 0; x < 9; ++x) {
        ASSERT_EQ(out.uAt(x, y), c.u) << c.r << "," << c.g << "," << c.b << " at " << x;
        ASSERT_EQ(out.vAt(x, y), c.v) << c.r << "," << c.g << "," << c.b << " at " << x;
      }
    }
  }
}

TEST(ArgbToYuv420, EverySampleIsTheExactValueRounded) {
  std::mt19937 random(5);
  const int sizes[][2] = {{2, 2},  {4, 2},  {6, 4},  {8, 2}, {10, 6},
                          {16, 4}, {18, 8}, {30, 2}, {64, 6}};
  constexpr double kTolerance = 0.5 + 0.02;  // rounding, and the 14-bit coefficients
  for (const auto& [width, height] : sizes) {
    for (const int pad : {0, 12}) {
      const Image image = randomImage(width, height, random, pad);
      const Planes out = converted(image, pad);
      for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
          ASSERT_NEAR(out.lumaAt(x, y), exactLuma(rgbOf(image.get(x, y))), kTolerance)
              << width << "x" << height << " at " << x << "," << y;
        }
      }
      for (int y = 0; y < height / 2; ++y) {
        for (int x = 0; x < width / 2; ++x) {
          const Rgb mean = blockMean(image, x, y);
          ASSERT_NEAR(out.uAt(x, y), exactU(mean), kTolerance) << width << "x" << height;
          ASSERT_NEAR(out.vAt(x, y), exactV(mean), kTolerance) << width << "x" << height;
        }
      }
    }
  }
}

TEST(ArgbToYuv420, AgreesWithLibswscaleWithinOneLevel) {
  std::mt19937 random(11);
  constexpr int kWidth = 70, kHeight = 24;
  // Random pixels, and flat areas with sharp coloured edges (what frames are made of).
  Image noisy = randomImage(kWidth, kHeight, random);
  Image edges(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x)
      edges.set(x, y, x < 23 ? 245 : 40, (x + y) % 7 < 3 ? 165 : 250, y < 9 ? 36 : 255);
  }
  SwsContext* sws =
      sws_getContext(kWidth, kHeight, AV_PIX_FMT_RGB32, kWidth, kHeight, AV_PIX_FMT_YUV420P,
                     SWS_AREA | SWS_FULL_CHR_H_INP | SWS_ACCURATE_RND, nullptr, nullptr, nullptr);
  ASSERT_NE(sws, nullptr);
  ASSERT_GE(sws_setColorspaceDetails(sws, sws_getCoefficients(SWS_CS_DEFAULT), 1,
                                     sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16),
            0);
  for (const Image* image : {&noisy, &edges}) {
    const Planes ours = converted(*image);
    Planes theirs(kWidth, kHeight);
    const RasterImage raster = image->raster();
    const std::uint8_t* const source[] = {raster.pixels};
    const int sourceStride[] = {raster.stride};
    std::uint8_t* const planes[] = {theirs.y.data(), theirs.u.data(), theirs.v.data()};
    sws_scale(sws, source, sourceStride, 0, kHeight, planes, theirs.strides);
    for (std::size_t i = 0; i < ours.y.size(); ++i)
      ASSERT_LE(std::abs(ours.y[i] - theirs.y[i]), 1) << "luma sample " << i;
    for (std::size_t i = 0; i < ours.u.size(); ++i) {
      ASSERT_LE(std::abs(ours.u[i] - theirs.u[i]), 1) << "U sample " << i;
      ASSERT_LE(std::abs(ours.v[i] - theirs.v[i]), 1) << "V sample " << i;
    }
  }
  sws_freeContext(sws);
}

// The encoder converts only what changed since the previous frame: over the conversion of
// the old image, converting the new one inside `area` must give the whole conversion of the
// new one. Areas with odd edges need the 2×2 blocks they cut into redone too, areas reaching
// past the image are clipped, and empty ones change nothing.
TEST(ArgbToYuv420, ConvertingAnAreaOverThePreviousImageEqualsConvertingTheWholeImage) {
  std::mt19937 random(5);
  constexpr int kWidth = 38, kHeight = 20;
  const Image before = randomImage(kWidth, kHeight, random, 8);
  for (const PixelBox area :
       {PixelBox{3, 5, 17, 9}, PixelBox{0, 0, kWidth, kHeight}, PixelBox{21, 1, 1, 1},
        PixelBox{-4, 13, 10, 40}, PixelBox{30, -3, 20, 6}, PixelBox{9, 9, 0, 5}}) {
    Image after = before;
    std::uniform_int_distribution<int> level(0, 255);
    const int right = std::min(area.x + area.width, kWidth);
    const int bottom = std::min(area.y + area.height, kHeight);
    for (int y = std::max(area.y, 0); y < bottom; ++y) {
      for (int x = std::max(area.x, 0); x < right; ++x)
        after.set(x, y, level(random), level(random), level(random));
    }
    Planes updated = converted(before, 3);
    argbToYuv420(after.raster(), updated.picture(), area);
    const Planes whole = converted(after, 3);
    EXPECT_EQ(updated.y, whole.y) << area.x << "," << area.y;
    EXPECT_EQ(updated.u, whole.u) << area.x << "," << area.y;
    EXPECT_EQ(updated.v, whole.v) << area.x << "," << area.y;
  }
  // Nothing outside the area's blocks is written.
  Planes untouched(kWidth, kHeight);
  argbToYuv420(before.raster(), untouched.picture(), {10, 4, 6, 2});
  for (int row = 0; row < kHeight; ++row) {
    for (int x = 0; x < kWidth; ++x) {
      const bool inside = x >= 10 && x < 16 && row >= 4 && row < 6;
      EXPECT_EQ(untouched.lumaAt(x, row) != 0, inside) << x << "," << row;
      if (x < kWidth / 2 && row < kHeight / 2) {
        const bool block = x >= 5 && x < 8 && row == 2;
        EXPECT_EQ(untouched.uAt(x, row) != 0, block) << x << "," << row;
        EXPECT_EQ(untouched.vAt(x, row) != 0, block) << x << "," << row;
      }
    }
  }
}

TEST(ArgbToYuv420, RejectsOddSizes) {
  Image image(3, 2);
  Planes planes(4, 2);
  EXPECT_THROW(argbToYuv420(image.raster(), planes.picture()), std::invalid_argument);
}

}  // namespace
}  // namespace camcov::viz
