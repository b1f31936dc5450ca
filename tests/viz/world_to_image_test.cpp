#include "viz/world_to_image.h"

#include <gtest/gtest.h>

namespace camcov::viz {
namespace {

using geometry::Vec2;

TEST(WorldToImage, WideWorldFillsTheWidthAndIsCentredVertically) {
  const WorldToImage t({{0.0, 0.0}, {20.0, 10.0}}, {0.0, 0.0, 220.0, 220.0}, 10.0);
  EXPECT_DOUBLE_EQ(t.scale(), 10.0);
  EXPECT_EQ(t({0.0, 0.0}), (Vec2{10.0, 160.0}));
  EXPECT_EQ(t({20.0, 10.0}), (Vec2{210.0, 60.0}));
}

TEST(WorldToImage, KeepsAspectAndFlipsY) {
  const WorldToImage t({{-5.0, -5.0}, {5.0, 5.0}}, {100.0, 50.0, 400.0, 200.0}, 0.0);
  EXPECT_DOUBLE_EQ(t.scale(), 20.0);  // the height limits
  const Vec2 origin = t({0.0, 0.0});
  EXPECT_EQ(origin, (Vec2{300.0, 150.0}));  // the area's centre
  EXPECT_DOUBLE_EQ(t({1.0, 0.0}).x - origin.x, 20.0);
  EXPECT_DOUBLE_EQ(t({0.0, 1.0}).y - origin.y, -20.0);  // up in the world is up in the image
}

TEST(WorldToImage, DegenerateBoxGetsAFiniteScale) {
  const WorldToImage t({{1.0, 1.0}, {1.0, 1.0}}, {0.0, 0.0, 100.0, 100.0}, 5.0);
  EXPECT_TRUE(std::isfinite(t.scale()));
  EXPECT_EQ(t({1.0, 1.0}), (Vec2{50.0, 50.0}));
}

}  // namespace
}  // namespace camcov::viz
