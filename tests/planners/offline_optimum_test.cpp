// The offline optimum against an independent reference: an exhaustive grid of poses
// for one camera, which the search must match or beat; and what the search reports about itself.
#include "planners/offline_optimum.h"

#include <gtest/gtest.h>

#include <numbers>

#include "planners/team_improvement.h"
#include "support/small_worlds.h"

namespace camcov::planners {
namespace {

struct Room {
  kinematics::World world = testing::roomWithTargetAndObstacle();
  reward::RewardModel model{params::RewardParams{}, std::numbers::pi / 6};
  StateValidity validity{1.0};
  Room() {
    model.setWorld(world);
    validity.setWorld(world);
  }
};

TEST(OfflineOptimum, OneCameraDoesAtLeastAsWellAsAnExhaustiveGridOfPoses) {
  Room s;
  double gridBest = -1e300;
  for (double x = -19.5; x <= 19.5; x += 0.5) {
    for (double y = -19.5; y <= 19.5; y += 0.5) {
      if (!s.validity.isValid({x, y})) continue;
      for (int k = 0; k < 72; ++k) {
        const geometry::Pose pose{x, y, k * std::numbers::pi / 36};
        gridBest = std::max(gridBest, s.model.reward(std::span(&pose, 1)));
      }
    }
  }
  OptimumOptions options;
  options.budget = 20000;
  Random random(1);
  const auto best = searchOptimum(s.model, s.validity, 1, options, random);
  ASSERT_TRUE(best);
  EXPECT_GE(best->terms.reward, gridBest - 1e-9) << "grid best " << gridBest;
  EXPECT_TRUE(s.validity.isValid(best->poses[0].position()));
  EXPECT_DOUBLE_EQ(best->terms.reward, s.model.reward(best->poses));
}

TEST(OfflineOptimum, ReportsHowItsBestGrewAndSpendsItsBudget) {
  Room s;
  OptimumOptions options;
  options.budget = 30000;
  options.samplesPerCamera = 200;
  Random a(7), b(7);
  const auto best = searchOptimum(s.model, s.validity, 2, options, a);
  ASSERT_TRUE(best);
  EXPECT_GE(best->evaluations, options.budget);
  EXPECT_LT(best->evaluations, options.budget + 2 * options.samplesPerCamera + 1)
      << "no move starts once the budget is spent";
  ASSERT_FALSE(best->curve.empty());
  for (std::size_t i = 1; i < best->curve.size(); ++i) {
    EXPECT_GT(best->curve[i].reward, best->curve[i - 1].reward);
    EXPECT_GE(best->curve[i].evaluations, best->curve[i - 1].evaluations);
  }
  EXPECT_EQ(best->curve.back().reward, best->terms.reward);
  EXPECT_EQ(best->curve.back().evaluations, best->foundAt);
  EXPECT_GE(best->foundInRound, 1);
  EXPECT_LE(best->foundInRound, best->rounds);
  EXPECT_TRUE(best->foundBy == "sampling" || best->foundBy == "re-placement" ||
              best->foundBy == "refinement");
  const auto again = searchOptimum(s.model, s.validity, 2, options, b);
  EXPECT_EQ(again->poses, best->poses) << "the same seed, the same search";
}

TEST(TeamImprovement, RefinementRaisesTheRewardKeepsCamerasValidAndOnlyMovesTheChosen) {
  Room s;
  std::vector<geometry::Pose> team{{-6, -6, 0.2}, {6, 6, 2.0}, {-8, 7, -1.0}};
  double value = s.model.reward(team);
  const double before = value;
  TeamImprovement moves(s.model, s.validity, 5000);
  scene::CameraSet firstAndThird = scene::CameraSet::only(0);
  firstAndThird.insert(2);
  moves.refineAll(team, value, firstAndThird);
  EXPECT_GT(value, before);
  EXPECT_DOUBLE_EQ(value, s.model.reward(team));
  EXPECT_EQ(team[1], (geometry::Pose{6, 6, 2.0}));
  for (const auto& p : team)
    EXPECT_TRUE(s.validity.isValid(p.position()));
  EXPECT_LE(moves.evaluations(), 5000);
}

}  // namespace
}  // namespace camcov::planners
