// A workspace that takes up another's instant (Sweep::keepSweepsOf): it answers the other's
// latest sweep of each camera without sweeping, keeps its own sweeps of the same arrangement (a
// world that did not change between two steps), and never answers from a sweep of another
// arrangement, even one built from the same world.
#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "support/random_worlds.h"
#include "visibility/sweep.h"

namespace camcov::visibility {
namespace {

using geometry::Pose;

std::vector<SeenInterval> copy(std::span<const SeenInterval> seen) {
  return {seen.begin(), seen.end()};
}

void expectSame(const std::vector<SeenInterval>& want, std::span<const SeenInterval> got) {
  ASSERT_EQ(want.size(), got.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(want[i].edge, got[i].edge);
    EXPECT_EQ(want[i].lo, got[i].lo);
    EXPECT_EQ(want[i].hi, got[i].hi);
  }
}

TEST(KeptSweeps, TakingAnInstantKeepsOwnSweepsOfTheSameArrangementOnly) {
  testing::SplitMix64 random{17};
  const kinematics::World world = testing::randomWorld(random);
  Occluders occluders(world);
  const scene::Lens lens{std::numbers::pi / 6};
  const Pose probe = testing::randomPose(random), measured = testing::randomPose(random);

  Sweep mine, theirs, afresh;
  const auto probed = copy(mine.seenBy(occluders, 0, probe, lens));
  const auto seenThere = copy(theirs.seenBy(occluders, 0, measured, lens));
  mine.keepSweepsOf(theirs);

  const auto reusedBefore = mine.counts().reused;
  expectSame(seenThere, mine.seenBy(occluders, 0, measured, lens));  // theirs, taken up
  expectSame(probed, mine.seenBy(occluders, 0, probe, lens));        // its own, kept
  EXPECT_EQ(mine.counts().reused, reusedBefore + 2);

  // The same world built again is another arrangement: swept again, to the same answer.
  Occluders rebuilt(world);
  expectSame(probed, mine.seenBy(rebuilt, 0, probe, lens));
  expectSame(copy(afresh.seenBy(rebuilt, 0, measured, lens)),
             mine.seenBy(rebuilt, 0, measured, lens));
  EXPECT_EQ(mine.counts().reused, reusedBefore + 2);
}

}  // namespace
}  // namespace camcov::visibility
