#include "planners/global_optimizer.h"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "support/small_worlds.h"

namespace camcov::planners {
namespace {

TEST(OptimizeGlobally, PlacesEveryCameraAtAValidPoseAndReportsTheTeamReward) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  reward::RewardModel model(params::RewardParams{}, std::numbers::pi / 6);
  model.setWorld(w);
  StateValidity validity(1.0);
  validity.setWorld(w);
  Random random(1);
  const auto result = optimizeGlobally(model, validity, 3, 200, random);
  ASSERT_TRUE(result);
  ASSERT_EQ(result->poses.size(), 3u);
  for (const auto& p : result->poses)
    EXPECT_TRUE(validity.isValid(p.position()));
  EXPECT_DOUBLE_EQ(result->reward, model.reward(result->poses));
  // Three cameras around a lone square see most of it.
  EXPECT_GT(model.evaluate(result->poses).coverage, 0.6);
}

TEST(OptimizeGlobally, HelperModelsOnMoreThreadsGiveTheSameResult) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  StateValidity validity(1.0);
  validity.setWorld(w);
  const auto makeModel = [&w] {
    reward::RewardModel model(params::RewardParams{}, std::numbers::pi / 6);
    model.setWorld(w);
    return model;
  };
  reward::RewardModel alone = makeModel(), main = makeModel();
  std::vector<reward::RewardModel> helpers;
  for (int t = 0; t < 3; ++t)
    helpers.push_back(makeModel());
  Random a(4), b(4);
  const auto one = optimizeGlobally(alone, validity, 3, 101, a);
  const auto four = optimizeGlobally(main, validity, 3, 101, b, helpers);
  ASSERT_TRUE(one && four);
  EXPECT_EQ(one->poses, four->poses);
  EXPECT_EQ(one->reward, four->reward);
  EXPECT_EQ(a.uniform(), b.uniform()) << "the same random numbers were drawn";
}

TEST(OptimizeGlobally, SameSeedSameResult) {
  const kinematics::World w = testing::roomWithTargetAndObstacle();
  reward::RewardModel model(params::RewardParams{}, std::numbers::pi / 6);
  model.setWorld(w);
  StateValidity validity(1.0);
  validity.setWorld(w);
  Random a(9), b(9);
  const auto ra = optimizeGlobally(model, validity, 2, 50, a);
  const auto rb = optimizeGlobally(model, validity, 2, 50, b);
  ASSERT_TRUE(ra && rb);
  EXPECT_EQ(ra->poses, rb->poses);
}

TEST(OptimizeGlobally, FailsWhenNoValidPoseExists) {
  kinematics::World w = testing::roomWithTargetAndObstacle();
  reward::RewardModel model(params::RewardParams{}, std::numbers::pi / 6);
  model.setWorld(w);
  StateValidity validity(100.0);  // d1 larger than the room
  validity.setWorld(w);
  Random random(1);
  EXPECT_FALSE(optimizeGlobally(model, validity, 1, 20, random));
}

}  // namespace
}  // namespace camcov::planners
