// ObservedSpeeds follows each object of the scene by its id, so recorded people entering and
// leaving (which reorders the world's rings) never make one person's step look like another's
// jump.
#include <gtest/gtest.h>

#include "safety/observed_speeds.h"
#include "support/small_worlds.h"

namespace camcov::safety {
namespace {

kinematics::World at(double t, std::vector<std::pair<std::uint32_t, double>> targets) {
  // Target id i is a unit square at (x, 10 · id): ids far apart, so a mix-up is a jump.
  kinematics::World w = camcov::testing::world(camcov::testing::box(-50, -50, 50, 50), {});
  w.time = t;
  for (const auto& [id, x] : targets) {
    w.targets.push_back(camcov::testing::box(x, 10.0 * id, x + 1, 10.0 * id + 1));
    w.targetIds.push_back(id);
  }
  return w;
}

TEST(ObservedSpeeds, FollowsEachObjectByItsIdWhenOthersComeAndGo) {
  ObservedSpeeds s;
  s.observe(at(0.0, {{0, 0.0}, {1, 0.0}, {2, 0.0}}));
  // Target 0 leaves; 1 and 2 move 0.1 m in 0.1 s (1 m/s): now world rings 0 and 1.
  s.observe(at(0.1, {{1, 0.1}, {2, 0.1}}));
  EXPECT_DOUBLE_EQ(s.fastestTarget(0), 1.0);
  EXPECT_DOUBLE_EQ(s.fastestTarget(1), 1.0);
  // Target 3 enters (nothing known: its speed is 0 until seen twice); 1 stops.
  s.observe(at(0.2, {{1, 0.1}, {2, 0.3}, {3, 5.0}}));
  EXPECT_DOUBLE_EQ(s.fastestTarget(0), 1.0) << "the larger of its last two steps";
  EXPECT_DOUBLE_EQ(s.fastestTarget(1), 2.0);
  EXPECT_DOUBLE_EQ(s.fastestTarget(2), 0.0);
  // Target 0 comes back (an id the recording reuses): no past, no jump from 0.1 s ago.
  s.observe(at(0.3, {{0, 4.0}, {1, 0.1}, {2, 0.3}, {3, 5.0}}));
  EXPECT_DOUBLE_EQ(s.fastestTarget(0), 0.0);
  EXPECT_DOUBLE_EQ(s.fastestTarget(1), 0.0);
  EXPECT_DOUBLE_EQ(s.fastestTarget(2), 2.0);
  EXPECT_DOUBLE_EQ(s.fastestTarget(3), 0.0);
}

}  // namespace
}  // namespace camcov::safety
