#include "planners/local_optimizer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "support/small_worlds.h"
#include "util/random.h"

namespace camcov::planners {
namespace {

// The reward of testing::roomWithTargetAndObstacle, with a field of view of θ = 30°.
reward::RewardModel roomModel() {
  reward::RewardModel model(params::RewardParams{}, std::numbers::pi / 6);
  model.setWorld(testing::roomWithTargetAndObstacle());
  return model;
}

// Three cameras in the middle 30 m of testing::roomWithTargetAndObstacle's room, any yaw.
std::vector<geometry::Pose> randomTeam(Random& random) {
  std::vector<geometry::Pose> team;
  for (int j = 0; j < 3; ++j) {
    team.push_back({random.uniform(-15, 15), random.uniform(-15, 15), random.uniform(-3, 3)});
  }
  return team;
}

TEST(LocalOptimizer, StepNeverLowersTheRewardAndRespectsLimits) {
  reward::RewardModel model = roomModel();
  const LocalOptimizer local{params::LocalParams{}};
  const StepLimits limits{0.2, 0.1};
  Random random(42);
  int moved = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<geometry::Pose> team = randomTeam(random);
    const double before = model.reward(team);
    const std::vector<geometry::Pose> original = team;
    const geometry::Pose next = local.step(model, team, 1, before, limits);
    EXPECT_EQ(team, original) << "the team is restored";
    team[1] = next;
    EXPECT_GE(model.reward(team), before);
    EXPECT_LE(geometry::distance(next.position(), original[1].position()),
              limits.maxTranslation + 1e-12);
    EXPECT_LE(std::abs(geometry::wrapAngle(next.yaw - original[1].yaw)),
              limits.maxRotation + 1e-12);
    if (!(next == original[1])) ++moved;
  }
  EXPECT_GT(moved, 50) << "most random poses can improve";
}

TEST(LocalOptimizer, ImproveMovesOnlyTheSelectedCameras) {
  reward::RewardModel model = roomModel();
  const LocalOptimizer local{params::LocalParams{}};
  std::vector<geometry::Pose> team{{-4, -3, 0.3}, {4, 3, 3.0}};
  const std::vector<StepLimits> limits(2, StepLimits{0.2, 0.1});
  const double before = model.reward(team);
  const double after = local.improve(model, team, scene::CameraSet::only(0), limits);
  EXPECT_EQ(team[1], (geometry::Pose{4, 3, 3.0}));
  EXPECT_GE(after, before);
  EXPECT_DOUBLE_EQ(after, model.reward(team));
}

TEST(LocalOptimizer, CompassStepNeverLowersTheRewardAndRespectsLimits) {
  reward::RewardModel model = roomModel();
  const LocalOptimizer compass{params::LocalParams{}, LocalOptimizer::Search::Compass};
  const StepLimits limits{0.2, 0.1};
  Random random(43);
  int moved = 0, sawMore = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<geometry::Pose> team = randomTeam(random);
    const auto before = model.terms(team);
    const std::vector<geometry::Pose> original = team;
    const geometry::Pose next = compass.step(model, team, 1, before.reward, limits);
    EXPECT_EQ(team, original) << "the team is restored";
    team[1] = next;
    const auto after = model.terms(team);
    EXPECT_GE(after.reward, before.reward);
    EXPECT_LE(geometry::distance(next.position(), original[1].position()),
              limits.maxTranslation + 1e-12);
    EXPECT_LE(std::abs(geometry::wrapAngle(next.yaw - original[1].yaw)),
              limits.maxRotation + 1e-12);
    if (!(next == original[1])) ++moved;
    if (after.coverage > before.coverage) ++sawMore;
  }
  EXPECT_GT(moved, 50);
  EXPECT_GT(sawMore, 10);
}

TEST(LocalOptimizer, CompassStepIsTheGradientsStepOrAWholeStepAlongOneAxis) {
  // The moves tried are the gradient's step (which makes the small moves) and the step's limit
  // along ±x, ±y and ±γ; a step goes to one of them or stays.
  reward::RewardModel model = roomModel();
  const LocalOptimizer gradient{params::LocalParams{}};
  const LocalOptimizer compass{params::LocalParams{}, LocalOptimizer::Search::Compass};
  // Long steps, so that a shorter move would often be the better one.
  const StepLimits limits{2.0, 1.0};
  Random random(47);
  int axisMoves = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<geometry::Pose> team = randomTeam(random);
    const double before = model.reward(team);
    const geometry::Pose here = team[1];
    std::vector<geometry::Pose> allowed{here, gradient.step(model, team, 1, before, limits)};
    for (int axis = 0; axis < 3; ++axis) {
      for (const double sign : {1.0, -1.0}) {
        geometry::Pose move = here;
        move[axis] += sign * (axis == 2 ? limits.maxRotation : limits.maxTranslation);
        move.yaw = geometry::wrapAngle(move.yaw);
        allowed.push_back(move);
      }
    }
    const geometry::Pose next = compass.step(model, team, 1, before, limits);
    EXPECT_NE(std::find(allowed.begin(), allowed.end(), next), allowed.end())
        << "trial " << trial << ": " << next.x << " " << next.y << " " << next.yaw;
    if (std::find(allowed.begin() + 2, allowed.end(), next) != allowed.end()) ++axisMoves;
  }
  EXPECT_GT(axisMoves, 25);
}

TEST(LocalOptimizer, CompassTurnsTowardsATargetJustOutOfViewWhereTheGradientSeesNothing) {
  // The target's nearest corner lies 0.05 rad beyond the left edge of the view: no small
  // change of yaw shows it (the reward is flat, its numerical gradient 0), a full step does.
  reward::RewardModel model = roomModel();
  const geometry::Vec2 camera{-0.5, -8.0};
  const double toCorner = std::atan2(-0.5 - camera.y, 0.5 - camera.x);  // the corner (0.5, -0.5)
  std::vector<geometry::Pose> team{{camera.x, camera.y, toCorner - std::numbers::pi / 6 - 0.05}};
  ASSERT_EQ(model.terms(team).coverage, 0.0);
  const StepLimits limits{0.2, 0.1};
  const double before = model.reward(team);
  const LocalOptimizer gradient{params::LocalParams{}};
  EXPECT_EQ(gradient.step(model, team, 0, before, limits), team[0]);
  const LocalOptimizer compass{params::LocalParams{}, LocalOptimizer::Search::Compass};
  team[0] = compass.step(model, team, 0, before, limits);
  EXPECT_GT(model.terms(team).coverage, 0.0);
}

}  // namespace
}  // namespace camcov::planners
