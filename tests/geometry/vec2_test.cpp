#include "geometry/vec2.h"

#include <gtest/gtest.h>

#include <numbers>

namespace camcov::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(WrapAngle, KeepsAnglesInsideMinusPiToPi) {
  EXPECT_DOUBLE_EQ(wrapAngle(0.5), 0.5);
  EXPECT_NEAR(wrapAngle(2 * kPi + 0.5), 0.5, 1e-15);
  EXPECT_NEAR(wrapAngle(-2 * kPi - 0.5), -0.5, 1e-15);
  EXPECT_NEAR(wrapAngle(degToRad(310)), degToRad(-50), 1e-15);
  EXPECT_LE(std::abs(wrapAngle(3 * kPi)), kPi);
}

TEST(Orient, SignTellsTurnDirection) {
  EXPECT_GT(orient({0, 0}, {1, 0}, {1, 1}), 0);  // left turn
  EXPECT_LT(orient({0, 0}, {1, 0}, {1, -1}), 0);
  EXPECT_EQ(orient({0, 0}, {1, 0}, {3, 0}), 0);  // collinear
}

TEST(Rotated, QuarterTurnMapsXToY) {
  const Vec2 v = rotated({1, 0}, kPi / 2);
  EXPECT_NEAR(v.x, 0, 1e-15);
  EXPECT_NEAR(v.y, 1, 1e-15);
}

}  // namespace
}  // namespace camcov::geometry
