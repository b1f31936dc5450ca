// A LINESTRING path unfolds into the loop kinematics follows: out along the line and back.
#include "scene/path_forms.h"

#include <gtest/gtest.h>

#include <vector>

namespace camcov::scene {
namespace {

using geometry::Vec2;
using Points = std::vector<Vec2>;

TEST(BackAndForthLoop, TwoPointsAreAlreadyABackAndForthLoop) {
  EXPECT_EQ(backAndForthLoop(Points{{3, 11}, {17, 11}}), (Points{{3, 11}, {17, 11}}));
}

TEST(BackAndForthLoop, ALongerLineComesBackThroughItsInnerPoints) {
  EXPECT_EQ(backAndForthLoop(Points{{15, 3}, {15, 7}, {12, 7}}),
            (Points{{15, 3}, {15, 7}, {12, 7}, {15, 7}}));
  EXPECT_EQ(backAndForthLoop(Points{{0, 0}, {1, 0}, {1, 1}, {0, 1}}),
            (Points{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 1}, {1, 0}}));
}

TEST(BackAndForthLoop, RepeatedPointsTakeNoTimeAndAreDropped) {
  EXPECT_EQ(backAndForthLoop(Points{{0, 0}, {0, 0}, {2, 0}, {2, 0}, {2, 3}}),
            (Points{{0, 0}, {2, 0}, {2, 3}, {2, 0}}));
}

TEST(BackAndForthLoop, OneDistinctPointIsLeftForTheCallerToRefuse) {
  EXPECT_EQ(backAndForthLoop(Points{{3, 3}}), (Points{{3, 3}}));
  EXPECT_EQ(backAndForthLoop(Points{{3, 3}, {3, 3}}), (Points{{3, 3}}));
  EXPECT_TRUE(backAndForthLoop(Points{}).empty());
}

}  // namespace
}  // namespace camcov::scene
