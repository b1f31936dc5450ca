#include "control/goal_assignment.h"

#include <gtest/gtest.h>

#include <vector>

namespace camcov::control {
namespace {

scene::CameraSpec camera(double halfFov, double speed = 1.0) {
  scene::CameraSpec c;
  c.maxVelocity = speed;
  c.maxAngularVelocity = 1.0;
  c.lens.halfFov = halfFov;
  return c;
}

TEST(AssignGoals, LikeCamerasTakeTheNearerGoalsAndTheTeamNeedsTheLongestTrip) {
  scene::Scene s;
  s.cameras = {camera(0.5), camera(0.5, 2.0)};
  const std::vector<geometry::Pose> at{{0, 0, 0}, {10, 0, 0}};
  const std::vector<geometry::Pose> goals{{9, 0, 0}, {1, 0, 0}};  // each nearer the other
  const GoalAssignment a = assignGoals(s, at, goals);
  EXPECT_EQ(a.goalOf, (std::vector<int>{1, 0}));
  EXPECT_DOUBLE_EQ(a.travelTime, 1.0) << "1 m at 1 m/s, and 1 m at 2 m/s";
}

TEST(AssignGoals, AGoalSampledForAnotherFieldOfViewIsNeverTaken) {
  scene::Scene s;
  s.cameras = {camera(0.3), camera(0.6)};
  const std::vector<geometry::Pose> at{{0, 0, 0}, {10, 0, 0}};
  const std::vector<geometry::Pose> goals{{10, 0, 0}, {0, 0, 3.0}};  // swapped would be free
  const GoalAssignment a = assignGoals(s, at, goals);
  EXPECT_EQ(a.goalOf, (std::vector<int>{0, 1}));
  EXPECT_DOUBLE_EQ(a.travelTime, 10.0) << "10 m at 1 m/s; the turn of 3 rad takes 3 s";
}

}  // namespace
}  // namespace camcov::control
