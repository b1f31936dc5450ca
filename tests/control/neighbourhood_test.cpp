// A camcov-dec camera's neighbourhood (control/neighbourhood.h): itself and its nearest teammates.
#include "control/neighbourhood.h"

#include <gtest/gtest.h>

#include <vector>

#include "support/small_worlds.h"

namespace camcov::control {
namespace {

using Members = std::vector<std::size_t>;

// Cameras on the x axis at the given abscissae.
std::vector<geometry::Pose> onALine(std::vector<double> xs) {
  std::vector<geometry::Pose> out;
  for (double x : xs)
    out.push_back({x, 0.0, 0.0});
  return out;
}

TEST(Neighbourhood, ATeamNoLargerThanItIsOneNeighbourhood) {
  const auto team = onALine({0, 100, 200});
  EXPECT_EQ(neighbourhood(team, 1, 3), (Members{0, 1, 2}));
  EXPECT_EQ(neighbourhood(team, 2, 5), (Members{0, 1, 2}));
}

TEST(Neighbourhood, HoldsTheCameraAndItsNearestTeammatesInIndexOrder) {
  const auto team = onALine({0, 10, 3, -2, 7});
  EXPECT_EQ(neighbourhood(team, 0, 3), (Members{0, 2, 3}));  // 2 m and 3 m away
  EXPECT_EQ(neighbourhood(team, 1, 2), (Members{1, 4}));
  EXPECT_EQ(neighbourhood(team, 4, 1), (Members{4}));
}

TEST(Neighbourhood, ATieGoesToTheLowerIndexAndACameraOnTopOfItDoesNotDisplaceIt) {
  // Cameras 0 and 3 are both 5 m from camera 2; camera 1 stands where camera 2 is.
  const auto team = onALine({-5, 0, 0, 5});
  EXPECT_EQ(neighbourhood(team, 2, 3), (Members{0, 1, 2}));
  EXPECT_EQ(neighbourhood(team, 1, 1), (Members{1}));
  EXPECT_EQ(neighbourhood(team, 2, 1), (Members{2}));
}

TEST(Neighbourhood, ItsSceneHasTheMembersCamerasInOrderAndTheRoom) {
  const scene::Scene scene = testing::sceneFromJson(R"js({
  "boundary": "POLYGON((0 0,20 0,20 20,0 20))",
  "targets": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((10 10))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(1 1)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(2 1)", "angle": 0, "maxVelocity": 2, "maxAngularVelocity": 1},
              {"pos": "POINT(3 1)", "angle": 0, "maxVelocity": 3, "maxAngularVelocity": 1}]})js");
  const Members members{0, 2};
  const scene::Scene sub = neighbourhoodScene(scene, members);
  ASSERT_EQ(sub.cameras.size(), 2u);
  EXPECT_EQ(sub.cameras[0].maxVelocity, 1.0);
  EXPECT_EQ(sub.cameras[1].maxVelocity, 3.0);
  EXPECT_EQ(sub.boundary, scene.boundary);
  EXPECT_TRUE(sub.targets.empty());
}

}  // namespace
}  // namespace camcov::control
