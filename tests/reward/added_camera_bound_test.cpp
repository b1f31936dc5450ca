// The bound that lets Algorithm 2 skip samples: never below the reward it bounds,
// whatever the pose — on an edge's line, at a vertex, inside a target, between two targets
// that share a side, with a field of view wider than a half-turn — and equal to it where
// nothing is occluded and the team sees nothing of what the camera does.
#include "reward/added_camera_bound.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "reward/reward_model.h"
#include "support/random_worlds.h"

namespace camcov::reward {
namespace {

using geometry::Pose;
using geometry::Vec2;
using Precision = AddedCameraBound::Precision;

// Poses the sampler can hardly draw and the bound must still hold at: the world's vertices,
// points on its edges and on their lines beyond them, and inside its targets.
std::vector<Pose> awkwardPoses(const kinematics::World& w, testing::SplitMix64& random) {
  std::vector<Pose> poses;
  const auto yaw = [&random] { return random.uniform(-std::numbers::pi, std::numbers::pi); };
  for (const auto* rings : {&w.targets, &w.obstacles}) {
    for (const geometry::Ring& ring : *rings) {
      Vec2 sum{0, 0};
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
        sum = sum + a;
        poses.push_back({a.x, a.y, yaw()});
        const Vec2 mid = geometry::lerp(a, b, 0.5), beyond = geometry::lerp(a, b, 2.5);
        poses.push_back({mid.x, mid.y, yaw()});
        poses.push_back({beyond.x, beyond.y, yaw()});
        // Looking along the edge, from its line.
        const Vec2 along = b - a;
        poses.push_back({beyond.x, beyond.y, std::atan2(-along.y, -along.x)});
      }
      const Vec2 centre = sum * (1.0 / static_cast<double>(ring.size()));
      poses.push_back({centre.x, centre.y, yaw()});
    }
  }
  return poses;
}

// The awkward poses, then `count` random ones.
std::vector<Pose> probePoses(const kinematics::World& w, testing::SplitMix64& random, int count) {
  std::vector<Pose> poses = awkwardPoses(w, random);
  for (int k = 0; k < count; ++k)
    poses.push_back(testing::randomPose(random));
  return poses;
}

// Importance weights in [0, 1] for every edge of every target.
void weighEdgesAtRandom(kinematics::World& w, testing::SplitMix64& random) {
  for (const geometry::Ring& ring : w.targets) {
    w.targetEdgeWeights.emplace_back();
    for (std::size_t e = 0; e < ring.size(); ++e)
      w.targetEdgeWeights.back().push_back(random.uniform(0.0, 1.0));
  }
}

TEST(AddedCameraBound, IsNeverBelowTheRewardOfTheTeamWithTheCameraAdded) {
  const std::vector<double> halfFovs{std::numbers::pi / 6, 0.49 * std::numbers::pi,
                                     0.6 * std::numbers::pi, 0.95 * std::numbers::pi};
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE(seed);
    testing::SplitMix64 random{seed};
    kinematics::World w = testing::randomWorld(random);
    // Every other world with importance weights: the bound is of the reward as weighted.
    if (seed % 2 == 0) {
      weighEdgesAtRandom(w, random);
    }
    const double theta = halfFovs[seed % halfFovs.size()];
    RewardModel model(params::RewardParams{}, {theta, 0.4, theta, 1.2, theta});
    model.setWorld(w);
    const std::vector<Pose> poses = probePoses(w, random, 300);
    AddedCameraBound bound;
    std::vector<double> terms;
    for (std::size_t size = 0; size < 5; ++size) {
      std::vector<Pose> team;
      for (std::size_t j = 0; j < size; ++j)
        team.push_back(testing::randomPose(random));
      const RewardTerms placed = model.evaluate(team);
      bound.prepare(model, team, placed);
      std::vector<Pose> added = team;
      added.emplace_back();
      for (const Pose& q : poses) {
        added.back() = q;
        const double reward = model.reward(added);
        const double coarse = bound.of(q, Precision::Coarse, terms);
        const double fine = bound.of(q, Precision::Fine, terms);
        // What the optimizer relies on: a sample scoring `reward` is never skipped against a
        // best of `reward`.
        EXPECT_FALSE(AddedCameraBound::cannotBeat(fine, reward))
            << "team of " << size << ", pose " << q.x << " " << q.y << " " << q.yaw << ": bound "
            << fine << " below reward " << reward;
        EXPECT_LE(fine, coarse + 1e-12) << "the fine bound is the tighter";
        if (HasFailure()) return;
      }
    }
  }
}

// Moving camera j of a team (a transit's yaws): the bound of the team with camera j at q,
// prepared from what the model's last terms() kept of the team, is never below its reward —
// for every j, in a team of one, with lenses unlike camera 0's, at awkward poses (on edges, at
// vertices, on the edge of no length of randomWorld()'s target with a repeated vertex); and
// placeAt(p) then ofYaw(γ) is the fine bound of (p, γ), but for rounding.
TEST(AddedCameraBound, IsNeverBelowTheRewardOfTheTeamWithOneCameraMoved) {
  int turnedAway = 0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE(seed);
    testing::SplitMix64 random{seed};
    kinematics::World w = testing::randomWorld(random);
    params::RewardParams params;
    // Every other world with importance weights, which the reward takes or leaves.
    if (seed % 2 == 0) {
      params.weighted = seed % 4 == 2;
      weighEdgesAtRandom(w, random);
    }
    // Camera 1 narrower and camera 3 wider than camera 0, whose θ varies with the seed.
    const double theta = seed % 3 == 0 ? 0.95 * std::numbers::pi : std::numbers::pi / 6;
    RewardModel model(params, {theta, 0.4, theta, 1.9, theta});
    model.setWorld(w);
    const std::vector<Pose> poses = probePoses(w, random, 150);
    AddedCameraBound bound;
    std::vector<double> terms;
    for (std::size_t size = 1; size <= 5; ++size) {
      std::vector<Pose> team;
      for (std::size_t j = 0; j < size; ++j)
        team.push_back(testing::randomPose(random));
      for (std::size_t j = 0; j < size; ++j) {
        model.terms(team);
        bound.prepareMoving(model, team, j);
        std::vector<Pose> moved = team;
        for (const Pose& q : poses) {
          moved[j] = q;
          const double reward = model.reward(moved);
          const double coarse = bound.of(q, Precision::Coarse, terms);
          const double fine = bound.of(q, Precision::Fine, terms);
          bound.placeAt(q.position(), terms);
          const double turning = bound.ofYaw(q.yaw);
          EXPECT_FALSE(AddedCameraBound::cannotBeat(fine, reward))
              << "camera " << j << " of " << size << " at " << q.x << " " << q.y << " " << q.yaw
              << ": bound " << fine << " below reward " << reward;
          EXPECT_LE(fine, coarse + 1e-12) << "the fine bound is the tighter";
          EXPECT_NEAR(turning, fine, 1e-12 * std::max(1.0, std::abs(fine)));
          if (HasFailure()) return;
          // Facing the other way: the bound must rule some such poses out to be of use.
          moved[j].yaw = geometry::wrapAngle(q.yaw + std::numbers::pi);
          const double awayReward = model.reward(moved);
          const double away = bound.ofYaw(moved[j].yaw);
          EXPECT_FALSE(AddedCameraBound::cannotBeat(away, awayReward));
          if (AddedCameraBound::cannotBeat(away, reward)) ++turnedAway;
        }
      }
    }
  }
  EXPECT_GT(turnedAway, 100) << "the bound rules out yaws that look away";
}

// Moving the one camera of a team of one is adding it to no team: the same bound.
TEST(AddedCameraBound, MovingTheOnlyCameraIsAddingItToNone) {
  testing::SplitMix64 random{7};
  const kinematics::World w = testing::randomWorld(random);
  RewardModel model(params::RewardParams{}, std::numbers::pi / 4);
  model.setWorld(w);
  const std::vector<Pose> none;
  AddedCameraBound added, moved;
  added.prepare(model, none, model.evaluate(none));
  const std::vector<Pose> one{testing::randomPose(random)};
  model.terms(one);
  moved.prepareMoving(model, one, 0);
  std::vector<double> terms;
  for (int k = 0; k < 100; ++k) {
    const Pose q = testing::randomPose(random);
    EXPECT_EQ(moved.of(q, Precision::Fine, terms), added.of(q, Precision::Fine, terms));
  }
}

// A 2 × 2 m square about the origin in a 100 m room, cameras with θ = 30°, and the bound
// prepared for a first camera.
struct LoneSquare {
  static constexpr double kTheta = std::numbers::pi / 6;
  static kinematics::World world() {
    kinematics::World w;
    w.boundary = {{-50, -50}, {50, -50}, {50, 50}, {-50, 50}};
    w.targets.push_back({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
    return w;
  }
  LoneSquare() {
    model.setWorld(world());
    bound.prepare(model, none, model.evaluate(none));
  }

  RewardModel model{params::RewardParams{}, kTheta};
  AddedCameraBound bound;
  std::vector<double> terms;
  const std::vector<Pose> none;
  const Pose faceOn{0, -10, std::numbers::pi / 2};  // (0, −10), looking at it
};

// Seen face on from (0, −10), only the square's near side faces the camera, so the fine bound
// is the reward itself.
TEST(AddedCameraBound, EqualsTheRewardWhereNothingIsOccluded) {
  LoneSquare s;
  const Pose q = s.faceOn;
  // Coverage 2/8 (the near side), utilization ∠ = 2·atan(1/9) over 2θ.
  const double expected = 1.0 * 0.25 + 0.2 * (2 * std::atan(1.0 / 9.0)) / (2 * s.kTheta);
  EXPECT_NEAR(s.bound.of(q, Precision::Fine, s.terms), expected, 1e-12);
  EXPECT_NEAR(s.model.reward(std::span(&q, 1)), expected, 1e-12);
  // Looking away: nothing to see, the bound is 0 as the reward.
  const Pose away{0, -10, -std::numbers::pi / 2};
  EXPECT_EQ(s.bound.of(away, Precision::Coarse, s.terms), 0.0);

  // With a first camera seeing that side already, a second one there adds no coverage.
  const std::vector<Pose> one{q};
  const RewardTerms placed = s.model.evaluate(one);
  s.bound.prepare(s.model, one, placed);
  const Pose twin{0.5, -10, std::numbers::pi / 2};
  const std::vector<Pose> two{q, twin};
  EXPECT_NEAR(s.bound.of(twin, Precision::Fine, s.terms), s.model.reward(two), 1e-12);
}

// The coarse bound takes the disc about the target for its angle: a little above what the
// disc itself subtends, 2·asin(r/d).
TEST(AddedCameraBound, CoarseBoundTakesTheTargetsDisc) {
  LoneSquare s;
  const double disc = 2 * std::asin(std::sqrt(2.0) / 10.0);
  const double coarse = s.bound.of(s.faceOn, Precision::Coarse, s.terms);
  EXPECT_GT(coarse, 0.25 + 0.2 * disc / (2 * s.kTheta));
  EXPECT_LT(coarse, 0.25 + 0.2 * 1.01 * disc / (2 * s.kTheta));
}

}  // namespace
}  // namespace camcov::reward
