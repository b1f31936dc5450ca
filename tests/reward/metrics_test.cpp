// The reward's terms on scenes small enough to compute by hand (paper eq. (2)-(8)).
#include "reward/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "reward/reward_model.h"
#include "support/random_worlds.h"

namespace camcov::reward {
namespace {

using geometry::Pose;

constexpr double kTheta = std::numbers::pi / 6;  // 30°, the benchmark's half-angle

kinematics::World unitSquareWorld() {
  kinematics::World w;
  w.boundary = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};
  w.targets = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  return w;
}

// Angle subtended at distance 5 by a centred side of length 1.
const double kSideAngle = 2 * std::atan(0.5 / 5.0);

TEST(RewardModel, CameraFacingOneSideSeesExactlyThatSide) {
  RewardModel model(params::RewardParams{}, kTheta);
  model.setWorld(unitSquareWorld());
  const Pose camera{0.5, -5.0, std::numbers::pi / 2};
  const RewardTerms t = model.evaluate(std::span(&camera, 1));
  EXPECT_NEAR(t.coverage, 0.25, 1e-12);
  EXPECT_NEAR(t.utilization, kSideAngle / (2 * kTheta), 1e-12);
  EXPECT_EQ(t.repulsion, 0.0);
  EXPECT_NEAR(t.reward, 0.25 + 0.2 * t.utilization, 1e-12);
  EXPECT_NEAR(visibleLengthOf(model.segments(), 0), 1.0, 1e-12);
}

TEST(RewardModel, TwoOpposedCamerasSeeTwoSidesAndAverageUtilization) {
  RewardModel model(params::RewardParams{}, kTheta);
  model.setWorld(unitSquareWorld());
  const std::vector<Pose> cameras{{0.5, -5.0, std::numbers::pi / 2},
                                  {0.5, 6.0, -std::numbers::pi / 2}};
  const RewardTerms t = model.evaluate(cameras);
  EXPECT_NEAR(t.coverage, 0.5, 1e-12);
  EXPECT_NEAR(t.utilization, kSideAngle / (2 * kTheta), 1e-12);  // mean of two equal views
}

TEST(RewardModel, UnlikeCamerasEachSeeWithTheirOwnFieldOfViewAndUtilizationAveragesThem) {
  // Camera 0 sees the bottom side with θ = 30°; camera 1, above and to the left, would see
  // nothing with 30° (the top and left sides lie 32° to 43° off its axis) but sees both
  // with its own 60°.
  const std::vector<Pose> cameras{{0.5, -5.0, std::numbers::pi / 2},
                                  {0.5 - 5.0 * std::tan(0.7), 6.0, -std::numbers::pi / 2}};
  const double wide = std::numbers::pi / 3;
  RewardModel unlike(params::RewardParams{}, std::vector<scene::Lens>{kTheta, wide});
  unlike.setWorld(unitSquareWorld());
  const RewardTerms t = unlike.evaluate(cameras);
  EXPECT_NEAR(visibleLengthOf(unlike.segments(), 0), 1.0, 1e-12);
  EXPECT_NEAR(visibleLengthOf(unlike.segments(), 1), 2.0, 1e-12);
  EXPECT_NEAR(t.coverage, 0.75, 1e-12);
  // Each camera alone, with its own θ: the team's utilization is their mean (eq. (5)).
  RewardModel narrow(params::RewardParams{}, kTheta), wideOnly(params::RewardParams{}, wide);
  narrow.setWorld(unitSquareWorld());
  wideOnly.setWorld(unitSquareWorld());
  const double u0 = narrow.evaluate(std::span(&cameras[0], 1)).utilization;
  const double u1 = wideOnly.evaluate(std::span(&cameras[1], 1)).utilization;
  EXPECT_GT(u1, 0.0);
  EXPECT_NEAR(t.utilization, 0.5 * (u0 + u1), 1e-12);
  EXPECT_EQ(narrow.evaluate(std::span(&cameras[1], 1)).coverage, 0.0) << "30° sees nothing";
}

TEST(RewardModel, CameraLookingAwaySeesNothing) {
  RewardModel model(params::RewardParams{}, kTheta);
  model.setWorld(unitSquareWorld());
  const Pose camera{0.5, -5.0, -std::numbers::pi / 2};
  const RewardTerms t = model.evaluate(std::span(&camera, 1));
  EXPECT_EQ(t.coverage, 0.0);
  EXPECT_EQ(t.utilization, 0.0);
  double total = 0;
  for (const auto& s : model.segments())
    total += visibility::length(s);
  EXPECT_NEAR(total, 4.0, 1e-12) << "unseen segments still tile the perimeter";
}

TEST(Repulsion, SumsObjectAndCameraPairsWithinD2) {
  const kinematics::World w = unitSquareWorld();
  // 1.5 m below the square: 1/1.5²; the second camera is 1 m from the first (1/1²) and
  // 2.5 m from the square (beyond d2 = 2).
  const std::vector<Pose> cameras{{0.5, -1.5, 0}, {0.5, -2.5, 0}};
  EXPECT_NEAR(repulsion(w, cameras, 2.0), 1.0 / 2.25 + 1.0, 1e-12);
  EXPECT_EQ(repulsion(w, std::span(cameras.data(), 1), 1.5), 0.0) << "d2 is exclusive";
}

TEST(Invdist, IsFiniteForContact) {
  EXPECT_EQ(invdist(3.0, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(invdist(0.5, 2.0), 4.0);
  EXPECT_DOUBLE_EQ(invdist(0.0, 2.0), 1.0 / (kMinDistance * kMinDistance));
}

TEST(Combine, IsEquationEight) {
  params::RewardParams p;
  p.lambda1 = 2.0;
  p.lambda2 = 0.5;
  p.lambda3 = 3.0;
  EXPECT_DOUBLE_EQ(combine(p, 0.5, 0.4, 0.1), 2.0 * 0.5 + 0.5 * 0.4 - 3.0 * 0.1);
}

// Against the reward itself: teams of one to three cameras anywhere in random worlds (no seen
// edge shared by two targets there), with weights drawn for each team, never score above it.
TEST(RewardCeiling, NoTeamScoresAboveItAndRepulsionThatAddsLeavesNone) {
  testing::SplitMix64 random{11};
  for (int world = 0; world < 20; ++world) {
    const kinematics::World w = testing::randomWorld(random);
    for (int team = 0; team < 100; ++team) {
      params::RewardParams p;
      p.lambda1 = random.uniform(0, 2);
      p.lambda2 = random.uniform(0, 2);
      p.lambda3 = random.uniform(0, 0.1);
      RewardModel model(p, kTheta);
      model.setWorld(w);
      std::vector<Pose> cameras(1 + team % 3);
      for (Pose& c : cameras)
        c = testing::randomPose(random);
      EXPECT_LE(model.reward(cameras), rewardCeiling(p)) << world << " " << team;
    }
  }
  params::RewardParams p;
  p.lambda1 = 0.5;
  p.lambda2 = 0.25;
  EXPECT_EQ(rewardCeiling(p), 0.75);
  p.lambda3 = -1.0;
  EXPECT_EQ(rewardCeiling(p), std::numeric_limits<double>::infinity());
}

TEST(Coverage, IsZeroWithoutPerimeter) {
  EXPECT_EQ(coverage({}, 0.0), 0.0);
}

}  // namespace
}  // namespace camcov::reward
