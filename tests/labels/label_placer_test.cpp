// The label placer on hand-made pictures: what it keeps labels off, the order it takes
// candidates in, and when it gives up.
#include <gtest/gtest.h>

#include <vector>

#include "labels/label_placer.h"

namespace camcov::labels {
namespace {

const Box kCanvas{{0.0, 0.0}, {100.0, 100.0}};

Box box(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y1}};
}

TEST(LabelPlacer, TakesTheFirstCandidateThatIsClear) {
  LabelPlacer placer(kCanvas, 0.0);
  placer.avoidLine(std::vector<Vec2>{{0.0, 50.0}, {100.0, 50.0}}, false);
  const std::vector<Box> candidates{box(10, 45, 30, 55), box(10, 20, 30, 30), box(10, 60, 30, 70)};
  EXPECT_EQ(placer.place(candidates), 1u) << "the first crosses the line";
  ASSERT_EQ(placer.placed().size(), 1u);
  EXPECT_EQ(placer.placed()[0].min, (Vec2{10.0, 20.0}));
}

TEST(LabelPlacer, KeepsLabelsOffEachOtherAndTheGap) {
  LabelPlacer placer(kCanvas, 2.0);
  const std::vector<Box> same{box(10, 10, 30, 20)};
  EXPECT_EQ(placer.place(same), 0u);
  EXPECT_FALSE(placer.place(same)) << "two labels at one spot";
  const std::vector<Box> touching{box(31, 10, 50, 20)};
  EXPECT_FALSE(placer.place(touching)) << "1 px away, closer than the gap";
  const std::vector<Box> apart{box(33, 10, 50, 20)};
  EXPECT_EQ(placer.place(apart), 0u);
}

TEST(LabelPlacer, KeepsLabelsOutOfFilledAreasButNotOutOfLoops) {
  const std::vector<Vec2> square{{20, 20}, {80, 20}, {80, 80}, {20, 80}};
  const std::vector<Box> inside{box(40, 40, 60, 50)};
  LabelPlacer filled(kCanvas, 0.0);
  filled.avoidArea(square);
  EXPECT_FALSE(filled.place(inside)) << "inside an object, touching none of its edges";
  LabelPlacer loop(kCanvas, 0.0);
  loop.avoidLine(square, true);
  EXPECT_EQ(loop.place(inside), 0u) << "inside a path's loop is free";
  const std::vector<Box> onTheClosingEdge{box(15, 40, 25, 50)};
  EXPECT_FALSE(loop.place(onTheClosingEdge)) << "the loop closes from the last point to the first";
}

TEST(LabelPlacer, KeepsLabelsInsideTheCanvasAndGivesUpWhenNothingIsClear) {
  LabelPlacer placer(kCanvas, 0.0);
  placer.avoidBox(box(0, 0, 100, 40));
  const std::vector<Box> candidates{box(-5, 50, 20, 60), box(10, 30, 30, 45)};
  EXPECT_FALSE(placer.place(candidates));
  EXPECT_TRUE(placer.placed().empty());
}

TEST(SegmentMeetsBox, CrossingTouchingAndMissing) {
  const Box b = box(0, 0, 10, 10);
  EXPECT_TRUE(segmentMeetsBox({-5, 5}, {15, 5}, b));
  EXPECT_TRUE(segmentMeetsBox({2, 2}, {3, 3}, b)) << "wholly inside";
  EXPECT_TRUE(segmentMeetsBox({10, -5}, {10, 15}, b)) << "along a side";
  EXPECT_FALSE(segmentMeetsBox({11, -5}, {11, 15}, b));
  EXPECT_FALSE(segmentMeetsBox({5, 16}, {16, 5}, b)) << "past the corner";
}

TEST(BoxesAround, StartInTheGivenDirectionAndTouchTheirPoint) {
  const double gaps[] = {2.0};
  const auto boxes = boxesAround(box(0, 0, 10, 10), {20.0, 6.0}, {0.0, -1.0}, gaps);
  ASSERT_EQ(boxes.size(), 16u);
  EXPECT_DOUBLE_EQ(boxes[0].max.y, -2.0) << "above, 2 px clear";
  EXPECT_DOUBLE_EQ((boxes[0].min.x + boxes[0].max.x) / 2, 5.0) << "centred";
  for (const Box& b : boxes)
    EXPECT_FALSE(geometry::overlaps(b, box(0, 0, 10, 10)));
}

}  // namespace
}  // namespace camcov::labels
