#include "planners/local_optimizer.h"

#include <gtest/gtest.h>

#include <numbers>

#include "support/small_worlds.h"
#include "util/random.h"

namespace camcov::planners {
namespace {

TEST(LocalOptimizer, StepNeverLowersTheRewardAndRespectsLimits) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  reward::RewardModel model(params::RewardParams{}, std::numbers::pi / 6);
  model.setWorld(w);
  const LocalOptimizer local{params::LocalParams{}};
  const StepLimits limits{0.2, 0.1};
  Random random(42);
  int moved = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<geometry::Pose> team;
    for (int j = 0; j < 3; ++j) {
      team.push_back({random.uniform(-15, 15), random.uniform(-15, 15), random.uniform(-3, 3)});
    }
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
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  reward::RewardModel model(params::RewardParams{}, std::numbers::pi / 6);
  model.setWorld(w);
  const LocalOptimizer local{params::LocalParams{}};
  std::vector<geometry::Pose> team{{-4, -3, 0.3}, {4, 3, 3.0}};
  const std::vector<StepLimits> limits(2, StepLimits{0.2, 0.1});
  const double before = model.reward(team);
  const double after = local.improve(model, team, 0b01, limits);
  EXPECT_EQ(team[1], (geometry::Pose{4, 3, 3.0}));
  EXPECT_GE(after, before);
  EXPECT_DOUBLE_EQ(after, model.reward(team));
}

}  // namespace
}  // namespace camcov::planners
