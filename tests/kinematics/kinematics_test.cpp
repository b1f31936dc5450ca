#include "kinematics/kinematics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "scene/scene_loader.h"
#include "support/test_paths.h"

namespace camcov::kinematics {
namespace {

using geometry::Vec2;

scene::Scene sceneWith(const std::string& objectJson) {
  return scene::parseScene(R"js({"boundary": "POLYGON((-20 -20,20 -20,20 20,-20 20))",
    "targets": [)js" + objectJson +
                               R"js(], "cameraFoV": 30,
    "cameras": [{"pos": "POINT(-19 -19)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1}]})js",
                           "test.json");
}

TEST(Kinematics, WorldAtZeroIsTheInitialPlacement) {
  const auto s = sceneWith(R"js({"shape": "POLYGON((0 0,2 0,1 1))", "path": "POLYGON((3 4, 8 4))",
                               "angularVelocity": 0.7})js");
  const World w = Kinematics(s).worldAt(0.0);
  EXPECT_EQ(w.targets.at(0), scene::initialPolygon(s.targets[0]));
  EXPECT_EQ(w.boundary, s.boundary);
}

TEST(Kinematics, RotatesShapeAboutReferencePoint) {
  // Static reference (5, 0), ω = 0.2 rad/s: a quarter turn takes π/0.4 s.
  const auto s = sceneWith(R"js({"shape": "POLYGON((1 0,2 0,2 1))", "path": "POLYGON((5 0))",
                               "angularVelocity": 0.2})js");
  const Kinematics k(s);
  const double quarterTurn = std::numbers::pi / 0.4;
  const World w = k.worldAt(quarterTurn);
  // Local (1, 0) -> rotated (0, 1) -> world (5, 1); local (2, 1) -> (-1, 2) -> (4, 2).
  EXPECT_NEAR(w.targets[0][0].x, 5.0, 1e-12);
  EXPECT_NEAR(w.targets[0][0].y, 1.0, 1e-12);
  EXPECT_NEAR(w.targets[0][2].x, 4.0, 1e-12);
  EXPECT_NEAR(w.targets[0][2].y, 2.0, 1e-12);
  EXPECT_NEAR(k.targetPose(0, quarterTurn).angle, std::numbers::pi / 2, 1e-12);
}

TEST(Kinematics, TranslationAndRotationCombine) {
  const auto s = sceneWith(R"js({"shape": "POLYGON((1 0,2 0,2 1))", "path": "POLYGON((0 0, 10 0))",
                               "velocity": 2.0, "angularVelocity": -0.5})js");
  const Kinematics k(s);
  const double t = 3.0;  // reference at (6, 0), angle -1.5 rad
  const World w = k.worldAt(t);
  const Vec2 expected = Vec2{6, 0} + geometry::rotated({2, 1}, -1.5);
  EXPECT_NEAR(w.targets[0][2].x, expected.x, 1e-12);
  EXPECT_NEAR(w.targets[0][2].y, expected.y, 1e-12);
}

TEST(Kinematics, DeformationThenRotationThenTranslation) {
  const auto s =
      sceneWith(R"js({"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((2 3))",
    "angularVelocity": 0.25,
    "deformation": {"period": 4, "keyframes": [{"time": 2, "shape": "POLYGON((-3 -1,3 -1,3 1,-3 1))"}]}})js");
  const Kinematics k(s);
  const World w = k.worldAt(1.0);  // halfway to the keyframe: local vertex 1 at (2, -1)
  const Vec2 expected = Vec2{2, 3} + geometry::rotated({2, -1}, 0.25);
  EXPECT_NEAR(w.targets[0][1].x, expected.x, 1e-12);
  EXPECT_NEAR(w.targets[0][1].y, expected.y, 1e-12);
  EXPECT_NEAR(geometry::signedArea(w.targets[0]), 8.0, 1e-12);  // 4 x 2
}

TEST(Kinematics, PublishedDynamic9MatchesTheLoopRule) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const auto s = scene::loadScene(testing::publishedScenesDir() / "dynamic9.json");
  const Kinematics k(s);
  const double t = 7.3;
  // Target 0: (0 5) <-> (0 -5) at 0.5 m/s.
  EXPECT_NEAR(k.targetPose(0, t).reference.y, 5.0 - 0.5 * t, 1e-12);
  // Target 3: loop (-8 3, -9 13, 13 11, 14 14, -12 12) at the default 1 m/s; the first leg is
  // sqrt(101) ≈ 10.05 m long, so at t = 7.3 it is 7.3 m along that leg.
  const Vec2 a{-8, 3}, b{-9, 13};
  const Vec2 expected = a + (b - a) * (7.3 / std::sqrt(101.0));
  EXPECT_NEAR(k.targetPose(3, t).reference.x, expected.x, 1e-12);
  EXPECT_NEAR(k.targetPose(3, t).reference.y, expected.y, 1e-12);
  // Later, on the third leg: cumulative length sqrt(101) + sqrt(488) ≈ 32.14 m.
  const double t3 = std::sqrt(101.0) + std::sqrt(488.0) + 1.0;
  const Vec2 c{13, 11}, d{14, 14};
  const Vec2 onThirdLeg = c + (d - c) * (1.0 / std::sqrt(10.0));
  EXPECT_NEAR(k.targetPose(3, t3).reference.x, onThirdLeg.x, 1e-9);
  EXPECT_NEAR(k.targetPose(3, t3).reference.y, onThirdLeg.y, 1e-9);
}

TEST(Kinematics, EveryPublishedWorldStaysCounterClockwiseAndFinite) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  World w;
  for (const auto& file : testing::jsonFilesIn(testing::publishedScenesDir())) {
    const auto s = scene::loadScene(file);
    const Kinematics k(s);
    for (double t = 0.0; t <= 30.0; t += 0.5) {
      k.worldAt(t, w);
      for (const auto& ring : w.targets) {
        ASSERT_GT(geometry::signedArea(ring), 0.0) << file << " t=" << t;
      }
      for (const auto& ring : w.obstacles) {
        ASSERT_GT(geometry::signedArea(ring), 0.0) << file << " t=" << t;
      }
    }
  }
}

TEST(Kinematics, ObjectsAtTheLoadersBoundsStayFiniteUntilTheLatestTimeTheCliAccepts) {
  // Regression (scene fuzzer): speeds and coordinates near the double range made v·t and ω·t
  // overflow, and the world filled with NaN. The loader now caps them (scene_validation.h);
  // at the caps, placement must stay finite for every time `camcov state --time` accepts.
  const auto s = sceneWith(R"js({"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))",
                               "path": "POLYGON((-10 0,10 0))", "velocity": 1e4,
                               "angularVelocity": -1e4})js");
  const Kinematics kinematics(s);
  for (const double t : {0.0, 1.0, 1e6, 1e9}) {
    const World world = kinematics.worldAt(t);  // named: a range-for would not extend its life
    for (const Vec2 v : world.targets[0]) {
      EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y)) << "t = " << t;
    }
  }
}

}  // namespace
}  // namespace camcov::kinematics
