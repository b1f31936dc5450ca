#include "kinematics/object_overlaps.h"

#include <gtest/gtest.h>

#include <string>

#include "geometry/ring.h"
#include "kinematics/kinematics.h"
#include "support/small_worlds.h"

namespace camcov::kinematics {
namespace {

// A 2 m square target driving along y = 0 at 1 m/s from x = -10 towards x = 10, and an
// obstacle given by `obstacle` (WKT).
scene::Scene drivingInto(const std::string& obstacle) {
  return testing::sceneFromJson(R"json({
    "boundary": "POLYGON((-20 -20,20 -20,20 20,-20 20))",
    "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))",
                 "path": "POLYGON((-10 0,10 0))", "velocity": 1.0}],
    "obstacles": [{"shape": ")json" +
                                obstacle + R"json(", "path": "POLYGON((0 0))"}],
    "cameraFoV": 30,
    "cameras": [{"pos": "POINT(0 -15)", "angle": 90, "maxVelocity": 1, "maxAngularVelocity": 1}]
  })json");
}

TEST(ObjectOverlaps, ATargetDrivingIntoAnObstacleIsFoundAtTheFirstInstantItsInteriorEnters) {
  // The squares touch at t = 8 s (the target's right side at x = -1) and overlap after.
  const auto found = findObjectOverlaps(drivingInto("POLYGON((-1 -1,1 -1,1 1,-1 1))"), 30.0, 0.1);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].first, "targets[0]");
  EXPECT_EQ(found[0].second, "obstacles[0]");
  EXPECT_NEAR(found[0].time, 8.1, 1e-9) << "touching at 8.0 is not overlapping";
  // The point named lies in both, at that instant.
  const World w = Kinematics(drivingInto("POLYGON((-1 -1,1 -1,1 1,-1 1))")).worldAt(found[0].time);
  for (const geometry::Ring* ring : {&w.targets[0], &w.obstacles[0]})
    EXPECT_NE(geometry::locate(*ring, found[0].near), geometry::Containment::Outside);
  EXPECT_EQ(describeOverlap(found[0]),
            "targets[0] and obstacles[0] pass through each other at t = 8.1 s near (-0.95, 0.00)");
}

TEST(ObjectOverlaps, OneInsideAnotherWithNoEdgeCrossingIsFoundAndTouchingOrApartIsNot) {
  // The obstacle encloses the whole drive: no edges cross, a vertex lies inside.
  const auto inside = findObjectOverlaps(drivingInto("POLYGON((-15 -5,15 -5,15 5,-15 5))"), 1, 0.1);
  ASSERT_EQ(inside.size(), 1u);
  EXPECT_EQ(inside[0].time, 0.0);
  // Beside the road, sharing the line y = 1 with the target's top side: touching only.
  EXPECT_TRUE(findObjectOverlaps(drivingInto("POLYGON((-5 1,5 1,5 3,-5 3))"), 30, 0.1).empty());
  EXPECT_TRUE(findObjectOverlaps(drivingInto("POLYGON((-5 8,5 8,5 9,-5 9))"), 30, 0.1).empty());
}

TEST(ObjectOverlaps, OnlyTheWindowAskedIsSampledAndAtMostSoManyInstants) {
  // Before t = 8 s nothing overlaps; a window of 7.9 s sees nothing.
  EXPECT_TRUE(findObjectOverlaps(drivingInto("POLYGON((-1 -1,1 -1,1 1,-1 1))"), 7.9, 0.1).empty());
  // A window of a million seconds at 0.1 s stops after kMaxInstants instants (100 s here):
  // the crossing at 8.1 s is still found.
  const auto far = findObjectOverlaps(drivingInto("POLYGON((-1 -1,1 -1,1 1,-1 1))"), 1e6, 0.1);
  ASSERT_EQ(far.size(), 1u);
  EXPECT_NEAR(far[0].time, 8.1, 1e-9);
  // A step so fine the count of instants would not fit an int: still capped, nothing found in
  // the first kMaxInstants nanoseconds.
  EXPECT_TRUE(findObjectOverlaps(drivingInto("POLYGON((-1 -1,1 -1,1 1,-1 1))"), 1e6, 1e-9).empty());
}

}  // namespace
}  // namespace camcov::kinematics
