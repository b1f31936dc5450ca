#include "scene/deformation.h"

#include <gtest/gtest.h>

#include "scene/scene_loader.h"

namespace camcov::scene {
namespace {

// A square that widens to a 4 x 2 rectangle at t = 1 s and back by t = 2 s.
constexpr const char* kBreathingSquare = R"js({
  "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
  "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))",
               "deformation": {"period": 2, "keyframes": [
                 {"time": 1, "shape": "POLYGON((-2 -1,2 -1,2 1,-2 1))"}]}}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(0 -5)", "angle": 90, "maxVelocity": 1, "maxAngularVelocity": 1}]})js";

TEST(LocalShapeAt, InterpolatesVertexByVertexThroughTheCycle) {
  const Scene s = parseScene(kBreathingSquare, "breathing.json");
  const MovingObject& square = s.targets.at(0);
  EXPECT_FALSE(square.isStatic());
  geometry::Ring shape;
  localShapeAt(square, 0.0, shape);
  EXPECT_DOUBLE_EQ(geometry::signedArea(shape), 4.0);  // 2 x 2
  localShapeAt(square, 1.0, shape);
  EXPECT_DOUBLE_EQ(geometry::signedArea(shape), 8.0);  // 4 x 2
  localShapeAt(square, 0.5, shape);
  EXPECT_DOUBLE_EQ(geometry::signedArea(shape), 6.0);  // 3 x 2, halfway
  localShapeAt(square, 1.5, shape);
  EXPECT_DOUBLE_EQ(geometry::signedArea(shape), 6.0);  // halfway back
  localShapeAt(square, 2.5, shape);
  EXPECT_DOUBLE_EQ(geometry::signedArea(shape), 6.0);  // next cycle
}

TEST(LocalShapeAt, ClockwiseShapeAndKeyframesAreReversedTogether) {
  // The same breathing square written clockwise: vertex correspondence must survive.
  const Scene s = parseScene(R"js({
    "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
    "targets": [{"shape": "POLYGON((-1 1,1 1,1 -1,-1 -1))", "path": "POLYGON((0 0))",
                 "deformation": {"period": 2, "keyframes": [
                   {"time": 1, "shape": "POLYGON((-2 1,2 1,2 -1,-2 -1))"}]}}],
    "cameraFoV": 30,
    "cameras": [{"pos": "POINT(0 -5)", "angle": 90, "maxVelocity": 1, "maxAngularVelocity": 1}]})js",
                             "cw.json");
  geometry::Ring shape;
  localShapeAt(s.targets[0], 0.5, shape);
  EXPECT_DOUBLE_EQ(geometry::signedArea(shape), 6.0);
}

TEST(LocalShapeAt, ObjectWithoutDeformationKeepsItsShape) {
  const Scene s = parseScene(kBreathingSquare, "b.json");
  MovingObject plain = s.targets[0];
  plain.deformation.reset();
  geometry::Ring shape;
  localShapeAt(plain, 0.7, shape);
  EXPECT_EQ(shape, plain.shape);
}

}  // namespace
}  // namespace camcov::scene
