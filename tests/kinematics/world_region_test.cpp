// A part of the world around a place (kinematics/world_region.h).
#include "kinematics/world_region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/ring.h"
#include "util/random.h"

namespace camcov::kinematics {
namespace {

using geometry::Box;
using geometry::Ring;
using geometry::Vec2;

Ring square(Vec2 centre, double half) {
  return {{centre.x - half, centre.y - half},
          {centre.x + half, centre.y - half},
          {centre.x + half, centre.y + half},
          {centre.x - half, centre.y + half}};
}

// Every vertex of `object` strictly inside `room`: nothing kept touches the clipped walls.
void expectStrictlyInside(const Ring& room, const Ring& object) {
  for (const Vec2 v : object)
    EXPECT_EQ(geometry::locate(room, v), geometry::Containment::Inside) << v.x << ", " << v.y;
}

// A 100 m square hall with three targets (ids 10, 11, 12, with edge weights) and an obstacle.
World hall() {
  World w;
  w.time = 4.2;
  w.boundary = square({0, 0}, 50);
  w.targets = {square({-30, -30}, 0.5), square({30, 30}, 0.5), square({-20, -30}, 1)};
  w.targetIds = {10, 11, 12};
  w.targetEdgeWeights = {{1, 1, 1, 1}, {0.5, 1, 1, 1}, {1, 0.25, 1, 1}};
  w.obstacles = {square({-35, -35}, 2)};
  w.obstacleIds = {3};
  return w;
}

TEST(WorldInRegion, KeepsWhatLiesInTheBoxWithItsIdsAndWeightsAndClipsTheRoomToIt) {
  const auto part = worldInRegion(hall(), {{-40, -40}, {-20.5, -25}}, {-32, -32});
  ASSERT_TRUE(part);
  EXPECT_EQ(part->time, 4.2);
  // Target 10 and the obstacle lie in the box; target 12 (x from -21 to -19) meets it and is
  // taken in whole; target 11 lies far outside.
  ASSERT_EQ(part->targets.size(), 2u);
  EXPECT_EQ(part->targetIds, (std::vector<std::uint32_t>{10, 12}));
  EXPECT_EQ(part->targetEdgeWeights[1], (std::vector<double>{1, 0.25, 1, 1}));
  EXPECT_EQ(part->obstacleIds, (std::vector<std::uint32_t>{3}));
  // The room is the box, grown to hold target 12 with a centimetre to spare, counter-clockwise.
  const Box room = geometry::boundingBox(part->boundary);
  EXPECT_DOUBLE_EQ(room.min.x, -40);
  EXPECT_DOUBLE_EQ(room.min.y, -40);
  EXPECT_NEAR(room.max.x, -18.99, 1e-12);
  EXPECT_DOUBLE_EQ(room.max.y, -25);
  EXPECT_GT(geometry::signedArea(part->boundary), 0.0);
  for (const Ring& object : part->targets)
    expectStrictlyInside(part->boundary, object);
  expectStrictlyInside(part->boundary, part->obstacles[0]);
}

TEST(WorldInRegion, GrowsOverObjectAfterObjectUntilItCutsNone) {
  // Staggered targets, each reaching past the next one's west side: taking one in reaches the
  // next.
  World w = hall();
  w.targets = {square({0, 0}, 1), square({1.8, 3}, 1), square({3.6, 0}, 1), square({5.4, 3}, 1)};
  w.targetIds = {};
  w.targetEdgeWeights = {};
  w.obstacles = {};
  w.obstacleIds = {};
  const auto part = worldInRegion(w, {{-2, -2}, {0.9, 5}}, {-1.5, 0});
  ASSERT_TRUE(part);
  EXPECT_EQ(part->targets.size(), 4u);
  EXPECT_EQ(part->targetIds, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_NEAR(geometry::boundingBox(part->boundary).max.x, 6.41, 1e-12);
  for (const Ring& object : part->targets)
    expectStrictlyInside(part->boundary, object);
}

TEST(WorldInRegion, InARoomThatIsNotConvexTakesTheAnchorsPieceOnly) {
  // A U: two arms (x < -10 and x > 10) joined below y = -40. A box across both arms above the
  // join meets the room in two pieces; the anchor's piece is the west arm's.
  World w;
  w.boundary = {{-50, -50}, {50, -50},  {50, 50},  {10, 50},
                {10, -40},  {-10, -40}, {-10, 50}, {-50, 50}};
  w.targets = {square({-30, 0}, 1), square({30, 0}, 1)};
  const auto part = worldInRegion(w, {{-40, -20}, {40, 20}}, {-20, 0});
  ASSERT_TRUE(part);
  EXPECT_EQ(part->targetIds, (std::vector<std::uint32_t>{0}));
  const Box room = geometry::boundingBox(part->boundary);
  EXPECT_DOUBLE_EQ(room.min.x, -40);
  EXPECT_DOUBLE_EQ(room.max.x, -10);
  EXPECT_NEAR(std::abs(geometry::signedArea(part->boundary)), 30.0 * 40.0, 1e-9);
  // From the east arm, the east piece.
  const auto east = worldInRegion(w, {{-40, -20}, {40, 20}}, {20, 0});
  ASSERT_TRUE(east);
  EXPECT_EQ(east->targetIds, (std::vector<std::uint32_t>{1}));
}

TEST(WorldInRegion, IsNoneWhereTheBoxHoldsTheRoomOrTheAnchorIsInNoPiece) {
  EXPECT_FALSE(worldInRegion(hall(), {{-60, -60}, {60, 60}}, {0, 0}));
  // Exactly the room's box: the part would be the world.
  EXPECT_FALSE(worldInRegion(hall(), {{-50, -50}, {50, 50}}, {0, 0}));
  // A box the objects grow to the room's.
  World w = hall();
  w.obstacles.push_back(square({0, 0}, 49.99));
  w.obstacleIds.push_back(4);
  EXPECT_FALSE(worldInRegion(w, {{-1, -1}, {1, 1}}, {0, 0}));
  // The anchor outside the box, or outside the room.
  EXPECT_FALSE(worldInRegion(hall(), {{-40, -40}, {-25, -25}}, {0, 0}));
  EXPECT_FALSE(worldInRegion(hall(), {{40, 40}, {70, 70}}, {60, 60}));
}

TEST(WorldInRegion, ABoxSharingTheRoomsWallsClipsToTheRoom) {
  // The box's west, south and east sides lie on the room's walls.
  const auto part = worldInRegion(hall(), {{-50, -50}, {50, -45}}, {0, -48});
  ASSERT_TRUE(part);
  const Box room = geometry::boundingBox(part->boundary);
  EXPECT_DOUBLE_EQ(room.min.x, -50);
  EXPECT_DOUBLE_EQ(room.max.x, 50);
  EXPECT_DOUBLE_EQ(room.min.y, -50);
  EXPECT_DOUBLE_EQ(room.max.y, -45);
  EXPECT_NEAR(geometry::signedArea(part->boundary), 100.0 * 5.0, 1e-9);
  EXPECT_TRUE(part->targets.empty());
}

TEST(WorldInRegion, OverRandomStarRoomsKeepsASimpleRoomHoldingTheAnchorAndEveryObjectKept) {
  // Star-shaped rooms of 12 spikes, small squares at random free places, random boxes: every
  // part is a simple counter-clockwise ring that holds the anchor, with every object kept
  // strictly inside it; a part never holds more objects than the world.
  Random random(11);
  int parts = 0;
  for (int trial = 0; trial < 300; ++trial) {
    World w;
    for (int k = 0; k < 12; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / 12, radius = random.uniform(10, 50);
      w.boundary.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    for (int i = 0; i < 40; ++i) {
      const Ring t = square({random.uniform(-40, 40), random.uniform(-40, 40)}, 0.5);
      bool inside = true;
      for (const Vec2 v : t)
        inside = inside && geometry::locate(w.boundary, v) == geometry::Containment::Inside;
      if (inside) w.targets.push_back(t);
    }
    const Vec2 anchor{random.uniform(-20, 20), random.uniform(-20, 20)};
    const double half = random.uniform(1, 30);
    const auto part = worldInRegion(w, geometry::grown(Box{anchor, anchor}, half), anchor);
    if (!part) continue;
    ++parts;
    SCOPED_TRACE(trial);
    EXPECT_FALSE(geometry::findSelfIntersection(part->boundary).found());
    EXPECT_GT(geometry::signedArea(part->boundary), 0.0);
    EXPECT_NE(geometry::locate(part->boundary, anchor, 1e-9), geometry::Containment::Outside);
    EXPECT_LE(part->targets.size(), w.targets.size());
    for (const Ring& object : part->targets)
      expectStrictlyInside(part->boundary, object);
  }
  EXPECT_GT(parts, 100);
}

}  // namespace
}  // namespace camcov::kinematics
