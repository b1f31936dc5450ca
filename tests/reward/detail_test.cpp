// A model that judges finely drawn objects simplified (RewardModel::setDetail): the same to the
// bit as a model of the world as drawn where nothing is fine, sharing the measured instant's
// arrangement; close to it, and much smaller, where something is.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>

#include "reward/reward_model.h"
#include "support/random_worlds.h"

namespace camcov::reward {
namespace {

using geometry::Pose;
using testing::randomPose;
using testing::randomWorld;

constexpr double kDetail = 0.01;  // m

void expectSameTerms(const RewardTerms& a, const RewardTerms& b) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.reward), std::bit_cast<std::uint64_t>(b.reward));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.coverage), std::bit_cast<std::uint64_t>(b.coverage));
}

// A world of random triangles and quadrilaterals, and the same with each target drawn finely:
// every edge split into 40 points along an arc bulging out by `bulge` metres.
kinematics::World finely(const kinematics::World& coarse, double bulge) {
  kinematics::World w = coarse;
  for (geometry::Ring& ring : w.targets) {
    geometry::Ring fine;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const geometry::Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
      const geometry::Vec2 d = b - a;
      if (geometry::norm(d) == 0.0) continue;  // the repeated vertex: the next edge starts there
      const geometry::Vec2 out = geometry::Vec2{d.y, -d.x} * (1.0 / geometry::norm(d));
      for (int k = 0; k < 40; ++k) {
        const double s = k / 40.0;
        fine.push_back(geometry::lerp(a, b, s) + out * (bulge * 4 * s * (1 - s)));
      }
    }
    ring = fine;
  }
  return w;
}

TEST(Detail, WhereNothingIsFineTheRewardsAndTheArrangementAreTheMeasuredOnes) {
  testing::SplitMix64 random{21};
  const scene::Lens lens(std::numbers::pi / 6);
  for (int round = 0; round < 20; ++round) {
    const kinematics::World world = randomWorld(random);
    RewardModel measured(params::RewardParams{}, lens), exact(params::RewardParams{}, lens),
        judged(params::RewardParams{}, lens);
    judged.setDetail(kDetail);
    measured.setWorld(world);
    exact.setInstant(measured);
    judged.setInstant(measured);
    EXPECT_EQ(&judged.occluders(), &measured.occluders()) << "the measured instant is shared";
    RewardModel fresh(params::RewardParams{}, lens);
    fresh.setDetail(kDetail);
    fresh.setWorld(world);
    for (int k = 0; k < 10; ++k) {
      const std::vector<Pose> team{randomPose(random), randomPose(random)};
      const RewardTerms reference = exact.terms(team);
      expectSameTerms(reference, judged.terms(team));
      expectSameTerms(reference, fresh.terms(team));
    }
  }
}

TEST(Detail, FineObjectsAreJudgedSimplifiedAndCloseToTheirDrawing) {
  testing::SplitMix64 random{22};
  const scene::Lens lens(std::numbers::pi / 4);
  double worst = 0.0;
  for (int round = 0; round < 20; ++round) {
    const kinematics::World world = finely(randomWorld(random), 0.002);
    RewardModel measured(params::RewardParams{}, lens), exact(params::RewardParams{}, lens),
        judged(params::RewardParams{}, lens), fresh(params::RewardParams{}, lens);
    judged.setDetail(kDetail);
    fresh.setDetail(kDetail);
    measured.setWorld(world);
    exact.setInstant(measured);
    judged.setInstant(measured);
    fresh.setWorld(world);
    std::size_t drawn = 0, judgedVertices = 0;
    for (std::size_t i = 0; i < world.targets.size(); ++i) {
      drawn += world.targets[i].size();
      judgedVertices += judged.world().targets[i].size();
    }
    EXPECT_LT(judgedVertices * 10, drawn)
        << judgedVertices << " of " << drawn << ": arcs bulging 2 mm are drawn as their chords";
    EXPECT_NE(&judged.occluders(), &measured.occluders());
    for (int k = 0; k < 10; ++k) {
      const std::vector<Pose> team{randomPose(random), randomPose(random)};
      const RewardTerms simplified = judged.terms(team);
      // Taking the instant and making the world afresh judge the same simplified world.
      expectSameTerms(simplified, fresh.terms(team));
      worst = std::max(worst, std::abs(simplified.coverage - exact.terms(team).coverage));
    }
  }
  // Chords within 2 mm of arcs of edges metres long: the coverage moves by far less than 1 %.
  EXPECT_LT(worst, 0.01);
}

}  // namespace
}  // namespace camcov::reward
