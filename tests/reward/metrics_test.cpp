// The reward's terms on scenes small enough to compute by hand (paper eq. (2)-(8)).
#include "reward/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "reward/reward_model.h"

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

TEST(Coverage, IsZeroWithoutPerimeter) {
  EXPECT_EQ(coverage({}, 0.0), 0.0);
}

}  // namespace
}  // namespace camcov::reward
