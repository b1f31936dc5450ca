#include "kinematics/path_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace camcov::kinematics {
namespace {

using geometry::Vec2;

void expectNear(Vec2 actual, Vec2 expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-12);
  EXPECT_NEAR(actual.y, expected.y, 1e-12);
}

TEST(PathMotion, OnePointPathIsStatic) {
  const std::vector<Vec2> path{{3, 4}};
  const PathMotion m(path, 1.0);
  expectNear(m.positionAt(0), {3, 4});
  expectNear(m.positionAt(123.4), {3, 4});
  EXPECT_EQ(m.loopLength(), 0.0);
}

TEST(PathMotion, TwoPointPathGoesBackAndForth) {
  // dynamic9's first target: (0, 5) <-> (0, -5) at 0.5 m/s; a lap is 20 m, 40 s.
  const std::vector<Vec2> path{{0, 5}, {0, -5}};
  const PathMotion m(path, 0.5);
  EXPECT_DOUBLE_EQ(m.loopLength(), 20.0);
  EXPECT_DOUBLE_EQ(m.period(), 40.0);
  expectNear(m.positionAt(0.0), {0, 5});
  expectNear(m.positionAt(7.3), {0, 1.35});   // 3.65 m down the first leg
  expectNear(m.positionAt(20.0), {0, -5});    // turning point
  expectNear(m.positionAt(25.0), {0, -2.5});  // 2.5 m back up
  expectNear(m.positionAt(40.0), {0, 5});     // wrap-around: home again
  expectNear(m.positionAt(41.0), {0, 4.5});
}

TEST(PathMotion, LoopVisitsEveryWaypointAtCumulativeArcLength) {
  // A 3-4-5 triangle: legs of 3, 4 and 5 metres, at 2 m/s.
  const std::vector<Vec2> path{{0, 0}, {3, 0}, {3, 4}};
  const PathMotion m(path, 2.0);
  EXPECT_DOUBLE_EQ(m.loopLength(), 12.0);
  expectNear(m.positionAt(1.5), {3, 0});
  expectNear(m.positionAt(2.5), {3, 2});
  expectNear(m.positionAt(3.5), {3, 4});
  expectNear(m.positionAt(4.75), {1.5, 2});     // middle of the closing leg
  expectNear(m.positionAt(6.0 + 1.5), {3, 0});  // second lap
}

TEST(PathMotion, RepeatedWaypointIsHarmless) {
  const std::vector<Vec2> path{{0, 0}, {0, 0}, {2, 0}};
  const PathMotion m(path, 1.0);
  expectNear(m.positionAt(1.0), {1, 0});
  for (double t = 0; t < 10; t += 0.25) {
    const Vec2 p = m.positionAt(t);
    EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
  }
}

}  // namespace
}  // namespace camcov::kinematics
