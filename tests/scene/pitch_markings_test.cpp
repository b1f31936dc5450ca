// The pitch extension's markings against the Laws of the Game (law 1) measured by hand: every
// line where the law puts it, the far end the mirror image of the near one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene/pitch_markings.h"

namespace camcov::scene {
namespace {

using geometry::Vec2;

TEST(PitchMarkings, LinesCirclesAndAreasWhereTheLawsPutThem) {
  const auto lines = pitchMarkings({105.0, 68.0});
  ASSERT_EQ(lines.size(), 12u);  // outline, halfway, circle, spot; per end area, box, spot, arc
  EXPECT_EQ(lines[0], (std::vector<Vec2>{{0, 0}, {105, 0}, {105, 68}, {0, 68}, {0, 0}}));
  EXPECT_EQ(lines[1], (std::vector<Vec2>{{52.5, 0}, {52.5, 68}}));
  for (const Vec2 p : lines[2])
    EXPECT_NEAR(geometry::distance(p, {52.5, 34}), 9.15, 1e-12);
  // Near end: the penalty area 16.5 m deep and 40.32 m wide, the goal area 5.5 m by 18.32 m.
  EXPECT_EQ(lines[4],
            (std::vector<Vec2>{{0, 13.84}, {16.5, 13.84}, {16.5, 54.16}, {0, 54.16}, {0, 13.84}}));
  EXPECT_EQ(lines[5],
            (std::vector<Vec2>{{0, 24.84}, {5.5, 24.84}, {5.5, 43.16}, {0, 43.16}, {0, 24.84}}));
  // The arc: 9.15 m from the spot (11 m out), starting and ending on the area's line.
  const auto& arc = lines[7];
  for (const Vec2 p : arc) {
    EXPECT_NEAR(geometry::distance(p, {11, 34}), 9.15, 1e-9);
    EXPECT_GE(p.x, 16.5 - 1e-9);
  }
  EXPECT_NEAR(arc.front().x, 16.5, 1e-9);
  EXPECT_NEAR(arc.back().x, 16.5, 1e-9);
  // The far end mirrors the near one about the halfway line.
  for (std::size_t k = 4; k < 8; ++k) {
    ASSERT_EQ(lines[k].size(), lines[k + 4].size());
    for (const Vec2 p : lines[k]) {
      const Vec2 mirrored{105.0 - p.x, p.y};
      const bool found = std::any_of(lines[k + 4].begin(), lines[k + 4].end(), [&](Vec2 q) {
        return geometry::distance(q, mirrored) < 1e-9;
      });
      EXPECT_TRUE(found) << "line " << k << " point (" << p.x << ", " << p.y << ")";
    }
  }
}

}  // namespace
}  // namespace camcov::scene
