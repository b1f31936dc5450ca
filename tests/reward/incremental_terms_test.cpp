// The optimizers' incremental terms against the terms made afresh from S, to the bit,
// over long random sequences of the calls the optimizers make: one camera probed and put
// back, a camera placed after the others, cameras taken away, θ changed, a new instant, the
// same world again (kept) or one a bit away (not). And the sums of runs (metrics.h) against the
// paper's sums over segments, to rounding.
#include "reward/incremental_terms.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>

#include "reward/incremental_repulsion.h"
#include "reward/metrics.h"
#include "reward/reward_model.h"
#include "support/random_worlds.h"

namespace camcov::reward {
namespace {

using geometry::Pose;
using testing::randomPose;
using testing::randomWorld;

// Bit for bit, with a readable failure.
void expectSameBits(double expected, double actual, const char* what) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(expected), std::bit_cast<std::uint64_t>(actual))
      << what << ": " << expected << " made afresh, " << actual << " kept up to date";
}

// One of the optimizers' calls: a probe of one camera (ε away, turned in place, or anywhere),
// the camera put back, a camera placed or taken away at the end, one camera's θ changed.
struct Caller {
  testing::SplitMix64 random;
  std::vector<Pose> team;
  std::vector<scene::Lens> thetas;
  std::vector<Pose> before;  // the team before the last probe

  void next() {
    const double what = random.uniform(0, 1);
    const auto j = static_cast<std::size_t>(random.uniform(0, static_cast<double>(team.size())));
    if (what < 0.3 && !before.empty() && before.size() == team.size()) {
      team = before;  // put back
    } else if (what < 0.55) {
      before = team;
      (random.uniform(0, 3) < 1   ? team[j].x
       : random.uniform(0, 2) < 1 ? team[j].y
                                  : team[j].yaw) += 1e-6;
    } else if (what < 0.68) {
      before = team;
      team[j].yaw = random.uniform(-std::numbers::pi, std::numbers::pi);  // turned in place
    } else if (what < 0.8) {
      before = team;
      team[j] = randomPose(random);
    } else if (what < 0.88 && team.size() < 12) {
      team.push_back(randomPose(random));
    } else if (what < 0.96 && team.size() > 1) {
      team.pop_back();
    } else {
      thetas[j] = random.uniform(0.2, 1.5);
    }
  }
};

TEST(IncrementalTerms, EqualTheTermsOfSToTheBitOverLongSequencesOfProbes) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    testing::SplitMix64 random{seed};
    visibility::Occluders occluders(randomWorld(random));
    visibility::Sweep afresh, kept;
    IncrementalTerms terms;
    Caller caller{{seed * 7919}, {}, std::vector<scene::Lens>(12, std::numbers::pi / 6), {}};
    for (int j = 0; j < 4; ++j)
      caller.team.push_back(randomPose(random));
    std::vector<visibility::Segment> s;
    for (int call = 0; call < 400; ++call) {
      if (call == 200) occluders.build(randomWorld(random));  // a new instant
      afresh.segments(occluders, caller.team, caller.thetas, s);
      const auto t = terms.evaluate(occluders, kept, caller.team, caller.thetas, {37.0, {}, 37.0});
      expectSameBits(coverage(s, 37.0), t.coverage, "coverage");
      expectSameBits(utilization(s, caller.team, caller.thetas), t.utilization, "utilization");
      if (HasFailure()) return;
      caller.next();
    }
  }
}

TEST(IncrementalRepulsion, EqualsRepulsionToTheBit) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE(seed);
    testing::SplitMix64 random{seed};
    kinematics::World world = randomWorld(random);
    std::vector<geometry::Box> boxes = objectBoxes(world);
    IncrementalRepulsion repulsionKept;
    Caller caller{{seed * 104729}, {}, std::vector<scene::Lens>(12, 0.5), {}};
    for (int j = 0; j < 4; ++j)
      caller.team.push_back(randomPose(random));
    for (int call = 0; call < 400; ++call) {
      if (call == 200) {  // a new instant
        world = randomWorld(random);
        boxes = objectBoxes(world);
        repulsionKept.reset();
      }
      // Cameras near objects and each other: most terms are not 0.
      for (Pose& p : caller.team) {
        p.x = std::clamp(p.x, -16.0, 16.0) * 0.5;
        p.y = std::clamp(p.y, -16.0, 16.0) * 0.5;
      }
      expectSameBits(repulsion(world, caller.team, 2.0),
                     repulsionKept.evaluate(world, boxes, caller.team, 2.0), "repulsion");
      if (HasFailure()) return;
      caller.next();
    }
  }
}

TEST(RewardModel, ProbesGiveTheRewardOfEvaluateToTheBit) {
  testing::SplitMix64 random{99};
  const kinematics::World world = randomWorld(random);
  RewardModel probing(params::RewardParams{}, std::numbers::pi / 6);
  RewardModel afresh(params::RewardParams{}, std::numbers::pi / 6);
  probing.setWorld(world);
  afresh.setWorld(world);
  Caller caller{{5}, {}, std::vector<scene::Lens>(12, std::numbers::pi / 6), {}};
  for (int j = 0; j < 5; ++j)
    caller.team.push_back(randomPose(random));
  for (int call = 0; call < 500; ++call) {
    expectSameBits(afresh.evaluate(caller.team).reward, probing.reward(caller.team), "reward");
    if (HasFailure()) return;
    caller.next();
    caller.thetas.assign(12, std::numbers::pi / 6);  // the model's θ are fixed
  }
}

// A RewardModel given the same world again (the next step of a scene whose objects stand still)
// keeps its occluder arrangement, and with it the sweeps and terms made for it; any other world,
// even one a vertex's last bit or an edge weight away, is a new arrangement. Either way every
// reward, measured or probed, is the one a model made afresh for the instant gives, to the bit.
// Every target edge weighted, so that a changed weight changes the reward.
kinematics::World weightedWorld(testing::SplitMix64& random) {
  kinematics::World w = randomWorld(random);
  for (const geometry::Ring& t : w.targets) {
    w.targetEdgeWeights.emplace_back();
    for (std::size_t e = 0; e < t.size(); ++e)
      w.targetEdgeWeights.back().push_back(random.uniform(0.1, 1.0));
  }
  return w;
}

TEST(KeptInstant, AWorldThatStaysKeepsItsArrangementAndEveryRewardStaysExact) {
  testing::SplitMix64 random{41};
  params::RewardParams params;
  params.weighted = true;
  const scene::Lens lens{std::numbers::pi / 6};
  RewardModel measured(params, lens), method(params, lens);
  kinematics::World world = weightedWorld(random);
  std::vector<Pose> team;
  for (int j = 0; j < 4; ++j)
    team.push_back(randomPose(random));
  std::uint64_t lastBuild = 0;
  int kept = 0, rebuilt = 0;

  for (int instant = 0; instant < 80; ++instant) {
    SCOPED_TRACE(instant);
    const double change = random.uniform(0, 1);
    bool same = instant > 0;
    if (change < 0.15) {
      world = weightedWorld(random);
      same = false;
    } else if (change < 0.25) {  // one vertex, one bit
      geometry::Vec2& v = world.targets[1][2];
      v.x = std::nextafter(v.x, 1e9);
      same = false;
    } else if (change < 0.35) {  // one weight
      world.targetEdgeWeights[0][1] *= 0.5;
      same = false;
    } else if (change < 0.4) {  // an obstacle's vertex
      world.obstacles[0][0].y = std::nextafter(world.obstacles[0][0].y, -1e9);
      same = false;
    }
    world.time = 0.1 * instant;  // the clock moves on whatever stays
    const kinematics::World copied = world;
    measured.setWorld(copied);
    method.setInstant(measured);
    RewardModel afresh(params, lens);
    afresh.setWorld(copied);

    const std::uint64_t build = measured.occluders().buildId();
    EXPECT_EQ(same, build == lastBuild);
    (same ? kept : rebuilt) += 1;
    lastBuild = build;

    expectSameBits(afresh.evaluate(team).reward, measured.evaluate(team).reward, "measured");
    // A method's probes of each camera, the camera put back after each (as the optimizers do),
    // and one camera left where the last probe took it (a camera that moved this step).
    for (std::size_t j = 0; j < team.size(); ++j) {
      const Pose here = team[j];
      for (const Pose step : {Pose{1e-6, 0, 0}, Pose{0, 0, 1e-6}, Pose{0.1, -0.1, 0.05}}) {
        team[j] = {here.x + step.x, here.y + step.y, here.yaw + step.yaw};
        expectSameBits(afresh.reward(team), method.reward(team), "probe");
      }
      team[j] = here;
      expectSameBits(afresh.reward(team), method.reward(team), "put back");
    }
    team[instant % team.size()].x += 0.05;
    if (HasFailure()) return;
  }
  EXPECT_GT(kept, 20);
  EXPECT_GT(rebuilt, 20);
}

// The sums of runs are the paper's sums over segments, up to rounding.
TEST(Metrics, RunSumsAreThePaperSumsOverSegments) {
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    SCOPED_TRACE(seed);
    testing::SplitMix64 random{seed};
    const visibility::Occluders occluders(randomWorld(random));
    std::vector<Pose> team;
    for (int j = 0; j < 6; ++j)
      team.push_back(randomPose(random));
    const std::vector<scene::Lens> thetas{0.5, 0.5, 0.3, 0.5, 1.2, 0.5};
    visibility::Sweep sweep;
    std::vector<visibility::Segment> s;
    sweep.segments(occluders, team, thetas, s);
    double length = 0.0, angles = 0.0;
    for (const auto& segment : s) {
      if (!segment.visibleBy.empty()) length += visibility::length(segment);
      for (std::size_t j = 0; j < team.size(); ++j) {
        if (segment.visibleBy.contains(j)) {
          angles += thetas[0].halfFov / thetas[j].halfFov *
                    subtendedAngle(segment.a, segment.b, team[j].position());
        }
      }
    }
    EXPECT_NEAR(visibleLength(s), length, 1e-12 * (1 + length));
    EXPECT_NEAR(utilization(s, team, thetas), angles / (2 * thetas[0].halfFov) / 6.0, 1e-13);
  }
}

TEST(Metrics, RunsJoinTouchingPiecesAndStopAtGapsAndEdgeEnds) {
  // Edge 0 from (0, 0) to (4, 0), then edge 1 up to (4, 4). Camera 0 sees [0, 1] and [1, 2]
  // (touching: one run); camera 1 sees [1, 2], then after a gap [3, 4] and all of edge 1 (two
  // runs on edge 0, one on edge 1: a run ends with its edge).
  using scene::CameraSet;
  const std::vector<visibility::Segment> s{{{0, 0}, {1, 0}, 0, 0, CameraSet::fromBits(1)},
                                           {{1, 0}, {2, 0}, 0, 0, CameraSet::fromBits(3)},
                                           {{2, 0}, {3, 0}, 0, 0, CameraSet::fromBits(0)},
                                           {{3, 0}, {4, 0}, 0, 0, CameraSet::fromBits(2)},
                                           {{4, 0}, {4, 4}, 0, 1, CameraSet::fromBits(2)}};
  EXPECT_EQ(visibleLength(s), 2.0 + 1.0 + 4.0);
  const geometry::Vec2 p0{0, -1}, p1{3.5, -1};
  const std::vector<Pose> team{{p0.x, p0.y, 0}, {p1.x, p1.y, 0}};
  const double camera0 = subtendedAngle({0, 0}, {2, 0}, p0);
  const double camera1 = subtendedAngle({1, 0}, {2, 0}, p1) + subtendedAngle({3, 0}, {4, 0}, p1) +
                         subtendedAngle({4, 0}, {4, 4}, p1);
  const std::vector<scene::Lens> thetas{0.5, 0.5};
  EXPECT_EQ(utilization(s, team, thetas), (camera0 + camera1) / (2 * 0.5) / 2);
}

}  // namespace
}  // namespace camcov::reward
