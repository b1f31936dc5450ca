// A RewardModel given the same world again (the next step of a scene whose objects stand still)
// keeps its occluder arrangement, and with it the sweeps and terms made for it; any other world,
// even one a vertex's last bit or an edge weight away, is a new arrangement. Either way every
// reward, measured or probed, is the one a model made afresh for the instant gives, to the bit.
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

void expectSameBits(double expected, double actual, const char* what) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(expected), std::bit_cast<std::uint64_t>(actual))
      << what << ": " << expected << " afresh, " << actual << " from the kept instant";
}

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

}  // namespace
}  // namespace camcov::reward
