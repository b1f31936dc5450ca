// Importance-weighted coverage (reward/metrics.h, kinematics/edge_importance.h): cases worked
// out on paper, unit weights against plain coverage to the bit, the probes' incremental terms
// against evaluate() to the bit, and the front told from the past alone.
#include <gtest/gtest.h>

#include <bit>
#include <numbers>

#include "kinematics/edge_importance.h"
#include "kinematics/kinematics.h"
#include "reward/metrics.h"
#include "reward/reward_model.h"
#include "scene/scene_loader.h"
#include "support/random_worlds.h"

namespace camcov::reward {
namespace {

using geometry::Pose;
constexpr double kTheta = std::numbers::pi / 6;

// A unit square target (at the origin, written counter-clockwise unless `shape` says) with the
// given keys, in a 40 m room.
scene::Scene squareScene(const std::string& keys,
                         const std::string& shape = "POLYGON((0 0,1 0,1 1,0 1))") {
  return scene::parseScene(
      R"j({"boundary": "POLYGON((-20 -20,20 -20,20 20,-20 20))", "cameraFoV": 30,
      "targets": [{"shape": ")j" +
          shape + R"j(", "path": "POINT(0 0)")j" + keys + R"j(}],
      "cameras": [{"pos": "POINT(-10 -10)", "angle": 0, "maxVelocity": 1,
                   "maxAngularVelocity": 1}]})j",
      "square.json");
}

RewardTerms termsAt(const scene::Scene& scene, double t, std::span<const Pose> cameras,
                    params::RewardParams params = {}) {
  RewardModel model(params, kTheta);
  model.setWorld(kinematics::Kinematics(scene).worldAt(t));
  return model.evaluate(cameras);
}

TEST(WeightedCoverage, SquareSeenFaceOnWithWeights3111IsHalf) {
  // The bottom edge (weight 3) of four unit edges: 3 of 3 + 1 + 1 + 1.
  const scene::Scene s = squareScene(R"(, "edgeWeights": [3, 1, 1, 1])");
  const Pose camera{0.5, -5.0, std::numbers::pi / 2};
  const RewardTerms t = termsAt(s, 0.0, std::span(&camera, 1));
  EXPECT_NEAR(t.coverage, 0.25, 1e-12);
  EXPECT_NEAR(t.weightedCoverage, 0.5, 1e-12);
  // The reward takes the weighted term: λ1 · 0.5 + λ2 · utilization.
  EXPECT_NEAR(t.reward, 0.5 + 0.2 * t.utilization, 1e-12);
}

TEST(WeightedCoverage, TwoSidesSeenFromTheCornerWithWeights3111AreTwoThirds) {
  // From (−5, −5) facing the square's centre: the bottom (3) and the left (1) edges.
  const scene::Scene s = squareScene(R"(, "edgeWeights": [3, 1, 1, 1])");
  const Pose camera{-5.0, -5.0, std::numbers::pi / 4};
  const RewardTerms t = termsAt(s, 0.0, std::span(&camera, 1));
  EXPECT_NEAR(t.coverage, 0.5, 1e-12);
  EXPECT_NEAR(t.weightedCoverage, 4.0 / 6.0, 1e-12);
}

TEST(WeightedCoverage, HalfAnEdgeCountsHalfItsWeight) {
  // A lens from (0.25, −5) just wide enough for the bottom edge's left half: θ = atan(0.25 / 5).
  const scene::Scene s = squareScene(R"(, "edgeWeights": [3, 1, 1, 1])");
  RewardModel model(params::RewardParams{}, std::atan(0.25 / 5.0));
  model.setWorld(kinematics::Kinematics(s).worldAt(0.0));
  const Pose camera{0.25, -5.0, std::numbers::pi / 2};
  const RewardTerms t = model.evaluate(std::span(&camera, 1));
  EXPECT_NEAR(t.coverage, 0.5 / 4.0, 1e-12);
  EXPECT_NEAR(t.weightedCoverage, 1.5 / 6.0, 1e-12);
}

TEST(WeightedCoverage, AClockwiseShapesWeightsFollowItsEdgesAsWritten) {
  // Written clockwise, edge 0 runs from (0 0) to (0 1): the left edge weighs 5.
  const scene::Scene s =
      squareScene(R"(, "edgeWeights": [5, 1, 1, 1])", "POLYGON((0 0,0 1,1 1,1 0))");
  const Pose camera{-5.0, 0.5, 0.0};
  const RewardTerms t = termsAt(s, 0.0, std::span(&camera, 1));
  EXPECT_NEAR(t.coverage, 0.25, 1e-12);
  EXPECT_NEAR(t.weightedCoverage, 5.0 / 8.0, 1e-12);
}

TEST(WeightedCoverage, ThePlainRewardIgnoresTheWeightsButStillMeasuresThem) {
  const scene::Scene s = squareScene(R"(, "edgeWeights": [3, 1, 1, 1])");
  const Pose camera{0.5, -5.0, std::numbers::pi / 2};
  params::RewardParams plain;
  plain.weighted = false;
  const RewardTerms t = termsAt(s, 0.0, std::span(&camera, 1), plain);
  EXPECT_NEAR(t.weightedCoverage, 0.5, 1e-12);
  EXPECT_NEAR(t.reward, 0.25 + 0.2 * t.utilization, 1e-12);
}

bool sameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(WeightedCoverage, UnitWeightsAreThePlainCoverageToTheBit) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    testing::SplitMix64 random{seed};
    kinematics::World world = testing::randomWorld(random);
    RewardModel plain(params::RewardParams{}, kTheta);
    plain.setWorld(world);
    for (const geometry::Ring& target : world.targets)
      world.targetEdgeWeights.emplace_back(target.size(), 1.0);
    RewardModel weighted(params::RewardParams{}, kTheta);
    weighted.setWorld(world);
    std::vector<Pose> team;
    for (int j = 0; j < 4; ++j) {
      team.push_back(testing::randomPose(random));
      const RewardTerms a = plain.evaluate(team), b = weighted.evaluate(team);
      EXPECT_TRUE(sameBits(a.coverage, b.weightedCoverage))
          << a.coverage << " " << b.weightedCoverage;
      EXPECT_TRUE(sameBits(a.reward, b.reward));
      EXPECT_TRUE(sameBits(b.coverage, b.weightedCoverage));
      EXPECT_TRUE(sameBits(weighted.terms(team).weightedCoverage, b.weightedCoverage));
    }
  }
}

TEST(WeightedCoverage, ProbesGiveTheWeightedTermsOfEvaluateToTheBit) {
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE(seed);
    testing::SplitMix64 random{seed};
    kinematics::World world = testing::randomWorld(random);
    for (const geometry::Ring& target : world.targets) {
      world.targetEdgeWeights.emplace_back();
      for (std::size_t e = 0; e < target.size(); ++e)
        world.targetEdgeWeights.back().push_back(random.uniform(0.0, 1.0));
    }
    RewardModel probing(params::RewardParams{}, kTheta), afresh(params::RewardParams{}, kTheta);
    probing.setWorld(world);
    afresh.setWorld(world);
    std::vector<Pose> team;
    for (int j = 0; j < 4; ++j)
      team.push_back(testing::randomPose(random));
    for (int call = 0; call < 200; ++call) {
      team[call % team.size()] = testing::randomPose(random);
      const RewardTerms a = afresh.evaluate(team), b = probing.terms(team);
      ASSERT_TRUE(sameBits(a.weightedCoverage, b.weightedCoverage))
          << a.weightedCoverage << " " << b.weightedCoverage;
      ASSERT_TRUE(sameBits(a.coverage, b.coverage));
      ASSERT_TRUE(sameBits(a.reward, b.reward));
      EXPECT_GE(a.weightedCoverage, 0.0);
      EXPECT_LE(a.weightedCoverage, 1.0);
    }
  }
}

TEST(FrontWeight, TheEdgeFacingTheMotionWeighsFrontWeightTheOthersOne) {
  const scene::Scene s = scene::parseScene(
      R"j({"boundary": "POLYGON((-20 -20,20 -20,20 20,-20 20))", "cameraFoV": 30,
        "targets": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))",
                     "path": "LINESTRING(0 0,10 0)", "velocity": 1, "frontWeight": 4}],
        "cameras": [{"pos": "POINT(-10 -10)", "angle": 0, "maxVelocity": 1,
                     "maxAngularVelocity": 1}]})j",
      "shuttle.json");
  const kinematics::Kinematics k(s);
  // Edge 1 (x = 0.5) faces +x. Weights are divided by the largest at the instant, 4.
  EXPECT_EQ(k.worldAt(2.0).targetEdgeWeights[0], (std::vector<double>{0.25, 1.0, 0.25, 0.25}));
  // At t = 0 nothing has moved yet: no front, every edge the same.
  EXPECT_EQ(k.worldAt(0.0).targetEdgeWeights[0], (std::vector<double>{1.0, 1.0, 1.0, 1.0}));
  // Just after the turn at x = 10 (t = 10): the past says it went right; the future, left.
  EXPECT_EQ(k.worldAt(10.1).targetEdgeWeights[0], (std::vector<double>{0.25, 1.0, 0.25, 0.25}));
  // Well after: it goes left, and edge 3 (x = −0.5) leads.
  EXPECT_EQ(k.worldAt(12.0).targetEdgeWeights[0], (std::vector<double>{0.25, 0.25, 0.25, 1.0}));
}

TEST(FrontWeight, AStandingTargetHasNoFront) {
  const scene::Scene s = squareScene(R"(, "frontWeight": 3, "frontAngle": 90)");
  EXPECT_EQ(kinematics::Kinematics(s).worldAt(5.0).targetEdgeWeights[0],
            std::vector<double>(4, 1.0));
}

TEST(FrontWeight, TheFrontAngleDecidesWhichEdgesLead) {
  // Moving along +x: normals at 0° (edge 1), ±90° (edges 0, 2), 180° (edge 3).
  const geometry::Ring square{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  const geometry::Vec2 right{1.0, 0.0};
  EXPECT_FALSE(kinematics::inFront(square, 0, right, std::numbers::pi / 3));
  EXPECT_TRUE(kinematics::inFront(square, 1, right, std::numbers::pi / 3));
  EXPECT_TRUE(kinematics::inFront(square, 0, right, 0.51 * std::numbers::pi));
  EXPECT_FALSE(kinematics::inFront(square, 3, right, 0.51 * std::numbers::pi));
  EXPECT_TRUE(kinematics::inFront(square, 3, right, std::numbers::pi));
}

}  // namespace
}  // namespace camcov::reward
