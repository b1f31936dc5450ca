// Why a camera does not see an edge (visibility/unseen_reason.h): each reason in a hand-made
// room, and agreement with the sweep on seeded random configurations — where the sweep says
// camera j does not see a segment, a reason is found; where it sees it, none is.
#include <gtest/gtest.h>

#include <numbers>

#include "random_scenes.h"
#include "support/small_worlds.h"
#include "visibility/sweep.h"
#include "visibility/unseen_reason.h"

namespace camcov::visibility {
namespace {

using Kind = ObjectRef::Kind;
constexpr double kQuarterTurn = std::numbers::pi / 2;
constexpr double kHalfFov = std::numbers::pi / 6;  // θ = 30°

// Edge `edge` of target 0 of the room (camcov::testing::roomWithTargetAndObstacle: a 1 m
// square at the origin, edges 0 bottom, 1 right, 2 top, 3 left), whole.
Segment edgeOfTarget(const kinematics::World& w, std::uint32_t edge) {
  const auto& ring = w.targets[0];
  return {ring[edge], ring[(edge + 1) % ring.size()], 0, edge, {}};
}

TEST(WhyUnseen, AnEdgeInFrontAndInViewIsInSight) {
  const auto w = camcov::testing::roomWithTargetAndObstacle();
  // From (0, -5) looking up (+y) the bottom edge faces the camera.
  const auto r = whyUnseen(w, {0, -5, kQuarterTurn}, kHalfFov, edgeOfTarget(w, 0));
  EXPECT_EQ(r.kind, UnseenKind::InSight);
}

TEST(WhyUnseen, TheFarSideOfATargetIsBehindItsTarget) {
  const auto w = camcov::testing::roomWithTargetAndObstacle();
  EXPECT_EQ(whyUnseen(w, {0, -5, kQuarterTurn}, kHalfFov, edgeOfTarget(w, 2)).kind,
            UnseenKind::BehindItsTarget);
  // Seen edge-on: the camera on the supporting line of the right edge.
  EXPECT_EQ(whyUnseen(w, {0.5, -5, kQuarterTurn}, kHalfFov, edgeOfTarget(w, 1)).kind,
            UnseenKind::BehindItsTarget);
}

TEST(WhyUnseen, AnEdgeOutsideTheWedgeIsOutsideTheFieldOfView) {
  const auto w = camcov::testing::roomWithTargetAndObstacle();
  // Looking down (−y), away from the target.
  EXPECT_EQ(whyUnseen(w, {0, -5, -kQuarterTurn}, kHalfFov, edgeOfTarget(w, 0)).kind,
            UnseenKind::OutsideFieldOfView);
}

TEST(WhyUnseen, TheFirstObjectOnTheLineOfSightBlocks) {
  const auto w = camcov::testing::roomWithTargetAndObstacle();
  // From (12, 0) looking at the right edge (x = 0.5) through the obstacle [5, 7] × [−0.5, 0.5].
  const auto r = whyUnseen(w, {12, 0, std::numbers::pi}, kHalfFov, edgeOfTarget(w, 1));
  EXPECT_EQ(r.kind, UnseenKind::Blocked);
  EXPECT_EQ(r.blocker, (ObjectRef{Kind::Obstacle, 0}));
  // A second target nearer the camera than the obstacle blocks first.
  auto two = w;
  two.targets.push_back(camcov::testing::box(9, -1, 10, 1));
  const auto nearer = whyUnseen(two, {12, 0, std::numbers::pi}, kHalfFov, edgeOfTarget(two, 1));
  EXPECT_EQ(nearer.blocker, (ObjectRef{Kind::Target, 1}));
}

TEST(WhyUnseen, ANotchOfTheBoundaryBlocks) {
  // An L-shaped room: the camera in one arm, the target round the corner in the other.
  const auto w = camcov::testing::world({{0, 0}, {20, 0}, {20, 4}, {4, 4}, {4, 20}, {0, 20}},
                                        {camcov::testing::box(1, 15, 2, 16)});
  const Segment bottom{{1, 15}, {2, 15}, 0, 0, {}};
  const auto r = whyUnseen(w, {16, 1, 2.4}, std::numbers::pi / 2.5, bottom);
  EXPECT_EQ(r.kind, UnseenKind::Blocked);
  EXPECT_EQ(r.blocker, (ObjectRef{Kind::Boundary, 0}));
}

TEST(WhyUnseen, ACameraInsideAnObjectOrOutsideTheRoomSeesNothing) {
  const auto w = camcov::testing::roomWithTargetAndObstacle();
  const auto inside = whyUnseen(w, {6, 0, std::numbers::pi}, kHalfFov, edgeOfTarget(w, 1));
  EXPECT_EQ(inside.kind, UnseenKind::InsideObject);
  EXPECT_EQ(inside.blocker, (ObjectRef{Kind::Obstacle, 0}));
  EXPECT_EQ(whyUnseen(w, {30, 0, std::numbers::pi}, kHalfFov, edgeOfTarget(w, 1)).kind,
            UnseenKind::OutsideBoundary);
}

// Degenerate for the comparison: the camera on an edge or a vertex, or the line of sight
// grazing a vertex, where the sweep's conventions (docs/visibility.md) decide by tolerance.
bool degenerate(const kinematics::World& w, const geometry::Pose& camera, geometry::Vec2 q) {
  constexpr double kNear = 1e-6;
  const geometry::Vec2 p = camera.position();
  const auto near = [&](const geometry::Ring& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto a = ring[i], b = ring[(i + 1) % ring.size()];
      if (geometry::distanceToSegment(p, a, b) < kNear) return true;
      if (geometry::distanceToSegment(a, p, q) < kNear && geometry::distance(a, q) > kNear)
        return true;
    }
    return false;
  };
  if (near(w.boundary)) return true;
  for (const auto& r : w.targets)
    if (near(r)) return true;
  for (const auto& r : w.obstacles)
    if (near(r)) return true;
  return false;
}

TEST(WhyUnseen, AgreesWithTheSweepOnRandomConfigurations) {
  Sweep sweep;
  std::vector<Segment> segments;
  std::size_t checked = 0, disagreements = 0;
  for (std::uint64_t index = 0; index < 2000; ++index) {
    const auto c = testing::randomCase(20261125, index);
    const Occluders occluders(c.world);
    sweep.segments(occluders, c.cameras, c.halfFov, segments);
    for (const Segment& s : segments) {
      // Pieces shorter than the sweep's tolerances are decided by them.
      if (length(s) < 1e-6) continue;
      for (std::size_t j = 0; j < c.cameras.size(); ++j) {
        if (degenerate(c.world, c.cameras[j], (s.a + s.b) * 0.5)) continue;
        const bool seen = s.visibleBy.contains(j);
        const bool explained =
            whyUnseen(c.world, c.cameras[j], c.halfFov, s).kind != UnseenKind::InSight;
        ++checked;
        if (seen == explained) {
          ++disagreements;
          ADD_FAILURE() << "case " << index << ", camera " << j << ": the sweep says "
                        << (seen ? "seen" : "unseen") << ", whyUnseen the opposite";
        }
      }
    }
  }
  EXPECT_GT(checked, 10000u);
  EXPECT_EQ(disagreements, 0u) << "of " << checked;
}

}  // namespace
}  // namespace camcov::visibility
