#include "planners/global_optimizer.h"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <vector>

#include "planners/visibility_sampler.h"
#include "support/random_worlds.h"
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

// Algorithm 2 as the paper writes it, every sample scored: the reference for the scoring that
// skips samples by their bound (reward/added_camera_bound.h).
std::vector<geometry::Pose> everySampleScored(reward::RewardModel& model,
                                              const StateValidity& validity, std::size_t cameras,
                                              int samplesPerCamera, Random& random) {
  std::vector<geometry::Pose> team;
  model.evaluate(team);
  VisibilitySampler sampler;
  for (std::size_t j = 0; j < cameras; ++j) {
    if (!sampler.focusOnUnseen(model, random)) return {};
    std::vector<geometry::Pose> samples;
    for (int k = 0; k < samplesPerCamera; ++k) {
      if (const auto pose = sampler.sample(random, validity, model.lens(j)))
        samples.push_back(*pose);
    }
    if (samples.empty()) return {};
    team.emplace_back();
    double best = -std::numeric_limits<double>::infinity();
    geometry::Pose chosen;
    for (const geometry::Pose& sample : samples) {
      team.back() = sample;
      if (const double score = model.reward(team); score > best) {
        best = score;
        chosen = sample;
      }
    }
    team.back() = chosen;
    model.evaluate(team);
  }
  return team;
}

TEST(OptimizeGlobally, SkippingSamplesByTheirBoundTakesTheSamePosesAsScoringEvery) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE(seed);
    testing::SplitMix64 worlds{seed};
    const kinematics::World w = testing::randomWorld(worlds);
    StateValidity validity(0.5);
    validity.setWorld(w);
    const auto makeModel = [&w] {
      reward::RewardModel model(params::RewardParams{}, {0.5, 0.5, 1.2, 0.5});
      model.setWorld(w);
      return model;
    };
    reward::RewardModel reference = makeModel(), pruned = makeModel();
    std::vector<reward::RewardModel> helpers;
    if (seed % 2 == 0) helpers.push_back(makeModel());
    Random a(seed), b(seed);
    const auto expected = everySampleScored(reference, validity, 4, 150, a);
    const auto result = optimizeGlobally(pruned, validity, 4, 150, b, helpers);
    ASSERT_EQ(expected.empty(), !result);
    if (result) {
      EXPECT_EQ(result->poses, expected);
    }
  }
}

}  // namespace
}  // namespace camcov::planners
