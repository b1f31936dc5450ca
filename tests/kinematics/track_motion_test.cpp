// Recorded motion (scene::Track): exact positions at the sample times, linear motion
// between them, the heading turning the short way, presence from the first sample to the last,
// and the world listing only the objects present with their scene indices.
#include <gtest/gtest.h>

#include <numbers>

#include "kinematics/kinematics.h"
#include "kinematics/track_motion.h"
#include "support/small_worlds.h"
#include "support/test_paths.h"

namespace camcov::kinematics {
namespace {

scene::Track walk() {
  // Two legs at different speeds, then a 4 s gap (bridged in a straight line).
  return {{1.0, 2.0, 4.0, 8.0}, {{0, 0}, {1, 0}, {1, 4}, {5, 4}}, {}};
}

TEST(TrackMotion, IsExactlyAtEachSampleAndLinearBetween) {
  const TrackMotion m(walk());
  const scene::Track t = walk();
  for (std::size_t k = 0; k < t.times.size(); ++k)
    EXPECT_EQ(m.positionAt(t.times[k]), t.positions[k]) << k;
  EXPECT_EQ(m.positionAt(1.5), (geometry::Vec2{0.5, 0}));
  EXPECT_EQ(m.positionAt(3.0), (geometry::Vec2{1, 2}));
  EXPECT_EQ(m.positionAt(6.0), (geometry::Vec2{3, 4}));  // across the gap
  // Outside the window the nearest sample: asked there only by the safety layer's bounds.
  EXPECT_EQ(m.positionAt(0.0), (geometry::Vec2{0, 0}));
  EXPECT_EQ(m.positionAt(9.0), (geometry::Vec2{5, 4}));
  EXPECT_DOUBLE_EQ(m.maxSpeed(), 2.0);  // 4 m in 2 s
}

TEST(TrackMotion, TurnsTheShortWayRound) {
  const double deg = std::numbers::pi / 180.0;
  const TrackMotion m(scene::Track{{0.0, 1.0}, {{0, 0}, {0, 0}}, {170 * deg, -170 * deg}});
  EXPECT_NEAR(m.headingAt(0.5), 180 * deg, 1e-12);  // through 180°, not through 0°
  EXPECT_NEAR(m.maxTurnRate(), 20 * deg, 1e-12);
}

TEST(TrackMotion, AWorldListsOnlyThePresentWithTheirSceneIndices) {
  const scene::Scene s =
      scene::loadScene(camcov::testing::testDataDir() / "scenes_tracks" / "comes_and_goes.json");
  const Kinematics k(s);
  // Target 0 from 1 s to 3 s, target 1 from 0.5 s to 2.5 s.
  const std::pair<double, std::vector<std::uint32_t>> expected[] = {
      {0.0, {}}, {0.5, {1}}, {1.0, {0, 1}}, {2.5, {0, 1}}, {2.75, {0}}, {3.0, {0}}, {3.25, {}}};
  for (const auto& [t, ids] : expected) {
    const World w = k.worldAt(t);
    EXPECT_EQ(w.targetIds, ids) << "t = " << t;
    ASSERT_EQ(w.targets.size(), ids.size()) << "t = " << t;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      geometry::Ring ring;
      k.placeTarget(ids[i], t, ring);
      EXPECT_EQ(w.targets[i], ring) << "t = " << t;
    }
  }
  // Recorded positions are where the target's reference point is, at the sample times.
  EXPECT_EQ(k.targetPose(0, 2.0).reference, (geometry::Vec2{0, 0}));
  EXPECT_EQ(k.targetPose(0, 1.5).reference, (geometry::Vec2{-2, 0}));
  EXPECT_NEAR(k.targetPose(1, 1.5).angle, std::numbers::pi / 4, 1e-12);  // 0° → 90° over 2 s
}

}  // namespace
}  // namespace camcov::kinematics
