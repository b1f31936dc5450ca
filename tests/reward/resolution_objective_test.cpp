// Resolution as the reward's coverage (RewardParams::resolution): the reward then counts each
// point by its credit min(1, ρ/ρ_min), so a far camera that sees a face earns a share of it and
// a near one all of it; the optimizers' probes (RewardModel::terms) give evaluate()'s terms to the
// bit and leave evaluate()'s S alone; a camera's own terms (termsAlone) count the same; off, or in
// a world that asks no resolution, nothing changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <random>
#include <vector>

#include "reward/metrics.h"
#include "reward/resolution_coverage.h"
#include "reward/reward_model.h"

namespace camcov::reward {
namespace {

using geometry::Pose;

// A 1 m square target in an 80 m room; cameras with a Full HD image over 60°: a face-on edge is
// resolved at 62.5 pixels per metre up to 1920 / (π/3) / 62.5 = 29.3 m.
kinematics::World room(bool asksResolution) {
  kinematics::World world;
  world.boundary = {{-40.0, -40.0}, {40.0, -40.0}, {40.0, 40.0}, {-40.0, 40.0}};
  world.targets = {{{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}};
  if (asksResolution) world.resolution = scene::ResolutionRequirement{62.5, false};
  return world;
}

std::vector<scene::Lens> fullHd(std::size_t cameras) {
  scene::Lens lens(std::numbers::pi / 6);
  lens.imageWidth = 1920;
  return std::vector<scene::Lens>(cameras, lens);
}

params::RewardParams counting(bool resolution) {
  params::RewardParams p;
  p.resolution = resolution;
  return p;
}

TEST(ResolutionObjective, AFarCameraEarnsItsShareOfTheDensityANearOneAllItSees) {
  RewardModel model(counting(true), fullHd(1));
  model.setWorld(room(true));
  ASSERT_TRUE(model.countsResolution());
  // On the +x axis facing the target: each sees exactly the face x = 0.5, a quarter of ∂T.
  const Pose near{3.0, 0.0, std::numbers::pi}, far{35.0, 0.0, std::numbers::pi};
  const RewardTerms n = model.evaluate(std::span(&near, 1));
  const RewardTerms f = model.evaluate(std::span(&far, 1));
  EXPECT_NEAR(n.coverage, 0.25, 1e-12);
  EXPECT_NEAR(f.coverage, 0.25, 1e-12);
  ASSERT_TRUE(n.resolutionCoverage && f.resolutionCoverage);
  EXPECT_NEAR(*n.resolutionCoverage, 0.25, 1e-12);  // ρ ≥ ρ_min within 3.5 m: full credit
  // From 34.5 m the face earns min(1, ρ(y)/ρ_min) at each point, ρ(y) = k·h/(h² + y²) with
  // k = W / 2θ and h = 34.5 m: integrated here by Simpson's rule over the face, over ∂T's 4 m.
  const double k = 1920.0 / (std::numbers::pi / 3.0), h = 34.5;
  const auto credit = [&](double y) { return std::min(1.0, k * h / (h * h + y * y) / 62.5); };
  const int n2 = 2000;
  double integral = credit(-0.5) + credit(0.5);
  for (int i = 1; i < n2; ++i)
    integral += (i % 2 == 1 ? 4.0 : 2.0) * credit(-0.5 + static_cast<double>(i) / n2);
  integral /= 3.0 * n2;
  EXPECT_NEAR(*f.resolutionCoverage, integral / 4.0, 1e-9);
  EXPECT_LT(*f.resolutionCoverage, 0.25);
  EXPECT_EQ(coverageTerm(model.params(), n), *n.resolutionCoverage);
  EXPECT_EQ(coverageTerm(model.params(), f), *f.resolutionCoverage);
}

TEST(ResolutionObjective, OffOrUnaskedTheRewardIsAsBefore) {
  const Pose far{35.0, 0.0, std::numbers::pi};
  for (const auto& [resolution, asks] : {std::pair{false, true}, std::pair{true, false}}) {
    RewardModel model(counting(resolution), fullHd(1));
    model.setWorld(room(asks));
    EXPECT_FALSE(model.countsResolution());
    const RewardTerms t = model.evaluate(std::span(&far, 1));
    EXPECT_FALSE(t.resolutionCoverage.has_value());
    EXPECT_EQ(coverageTerm(model.params(), t), t.weightedCoverage);
    EXPECT_EQ(model.terms(std::span(&far, 1)).reward, t.reward);
  }
}

TEST(ResolutionObjective, ProbesGiveEvaluatesTermsAndLeaveItsSegmentsAlone) {
  RewardModel model(counting(true), fullHd(3));
  model.setWorld(room(true));
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> coordinate(-28.0, 28.0), yaw(-3.14, 3.14);
  const std::vector<Pose> team{{4.0, 1.0, 3.0}, {-6.0, -2.0, 0.2}};
  model.evaluate(team);
  const std::vector<visibility::Segment> kept(model.segments().begin(), model.segments().end());
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Pose> probe(3);
    for (Pose& p : probe) {
      const double x = coordinate(random), y = coordinate(random);
      p = {x, y, yaw(random)};
    }
    const RewardTerms probed = model.terms(probe);
    ASSERT_EQ(model.segments().size(), kept.size());
    RewardModel fresh(counting(true), fullHd(3));
    fresh.setWorld(room(true));
    const RewardTerms evaluated = fresh.evaluate(probe);
    EXPECT_EQ(probed.reward, evaluated.reward) << trial;
    EXPECT_EQ(probed.resolutionCoverage, evaluated.resolutionCoverage) << trial;
    // A camera alone counts as a team of one does.
    const RewardTerms alone =
        termsAlone(fresh.world(), fresh.segments(), probe, fullHd(3), 0, fresh.params());
    RewardModel single(counting(true), fullHd(1));
    single.setWorld(room(true));
    const RewardTerms one = single.evaluate(std::span(probe.data(), 1));
    ASSERT_TRUE(alone.resolutionCoverage && one.resolutionCoverage);
    EXPECT_NEAR(*alone.resolutionCoverage, *one.resolutionCoverage, 1e-12) << trial;
  }
}

}  // namespace
}  // namespace camcov::reward
