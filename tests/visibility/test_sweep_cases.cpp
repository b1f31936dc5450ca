// Hand-made configurations for the camera sweep (Algorithm 1), one per degenerate case of
// docs/visibility.md, with the expected values worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "support/small_worlds.h"
#include "visibility/sweep.h"

namespace camcov::visibility {
namespace {

using camcov::testing::box;
using camcov::testing::world;
using geometry::Pose;
using geometry::Ring;
using geometry::Vec2;

constexpr double kPi = std::numbers::pi;
constexpr double kTight = 1e-12;

std::vector<Segment> segmentsOf(const kinematics::World& w, std::vector<Pose> cameras,
                                double halfFov) {
  Sweep sweep;
  std::vector<Segment> out;
  sweep.segments(Occluders(w), cameras, halfFov, out);
  return out;
}

double seenBy(const std::vector<Segment>& segments, unsigned camera) {
  double sum = 0.0;
  for (const Segment& s : segments) {
    if (s.visibleBy.contains(camera)) sum += length(s);
  }
  return sum;
}

double seenByAnyone(const std::vector<Segment>& segments) {
  double sum = 0.0;
  for (const Segment& s : segments) {
    if (!s.visibleBy.empty()) sum += length(s);
  }
  return sum;
}

double seenOf(const std::vector<Segment>& segments, std::uint32_t target) {
  double sum = 0.0;
  for (const Segment& s : segments) {
    if (s.target == target && !s.visibleBy.empty()) sum += length(s);
  }
  return sum;
}

const Ring kRoom = box(-10, -10, 10, 10);

TEST(CameraSweep, UnitSquareSeenFromBelowShowsExactlyItsBottomSide) {
  // The camera at (0, −5) looks up with θ = 30°: the bottom side lies in view, the left side is
  // edge-on (the camera is on its supporting line x = 0), the others face away. Coverage 1/4.
  const auto s = segmentsOf(world(kRoom, {box(0, 0, 1, 1)}), {{0, -5, kPi / 2}}, kPi / 6);
  EXPECT_NEAR(seenBy(s, 0) / 4.0, 0.25, kTight);
  for (const Segment& seg : s) {
    EXPECT_EQ(seg.visibleBy, scene::CameraSet::fromBits(seg.edge == 0 ? 1u : 0u))
        << "edge " << seg.edge;
  }
}

TEST(CameraSweep, CameraOnASupportingLineSeesThatEdgeAsZeroLength) {
  // From (−3, 0) on the line of the bottom side, looking along it (θ = 45°): only the left side
  // is seen, fully (its far end is atan(1/3) ≈ 18° up). Utilization: atan(1/3) / (π/2).
  const auto s = segmentsOf(world(kRoom, {box(0, 0, 1, 1)}), {{-3, 0, 0}}, kPi / 4);
  EXPECT_NEAR(seenBy(s, 0), 1.0, kTight);
  for (const Segment& seg : s) {
    if (!seg.visibleBy.empty()) {
      EXPECT_EQ(seg.edge, 3u);  // from (0, 1) to (0, 0)
    }
  }
}

TEST(CameraSweep, RayThroughVerticesOfTwoObjectsHandsOverCleanly) {
  // From the origin the ray of slope 1/2 passes through (2, 1), a corner of the near square,
  // and (4, 2), a corner of the far one. The near square's left side covers slopes [0, 1/2]; the
  // far square's left side, slopes [1/2, 3/4], is seen whole; its bottom (slopes [2/5, 1/2])
  // hides behind the near square.
  const auto s = segmentsOf(world(kRoom, {box(2, 0, 3, 1), box(4, 2, 5, 3)}), {{0, 0, 0}}, kPi / 4);
  EXPECT_NEAR(seenOf(s, 0), 1.0, kTight);
  EXPECT_NEAR(seenOf(s, 1), 1.0, kTight);
  for (const Segment& seg : s) {
    if (seg.target == 1 && seg.edge == 0) {
      EXPECT_TRUE(seg.visibleBy.empty());
    }
  }
}

TEST(CameraSweep, ThreeRingsCrossingAtOnePointHandOverCleanly) {
  // The target's side from (8, −1) to (18, 16), the obstacle's side from (7, 9) to (17, 13)
  // and the wall x = 16 all cross at (16, 12.6), each pair's crossing computed apart. From
  // (15, 4), looking over [0°, 240°], the side is seen from the floor y = 0 (at x = 8 + 1/1.7)
  // to the wall: 12.6/17 of its length √389. The obstacle lies behind it.
  const auto s = segmentsOf(world(box(0, 0, 16, 16), {{{8, -1}, {18, 16}, {-1, 2}}},
                                  {{{1, 0}, {4, 4.5}, {7, 9}, {17, 13}, {0, 7}}}),
                            {{15, 4, 2 * kPi / 3}}, 2 * kPi / 3);
  EXPECT_NEAR(seenBy(s, 0), 12.6 / 17 * std::sqrt(389.0), kTight);
}

TEST(CameraSweep, VertexAnUlpOffAnEdgeTouchesIt) {
  // The obstacle lies inside the target, its apex (30/7, 9/7) rounded an ulp off the target's
  // side from (10, 3) to (0, 0), towards the camera. From (5, 6) above, looking over
  // [220°, 340°], that side is seen whole, √109, and the obstacle behind it not at all.
  const Ring target{{0, 0}, {5, -5}, {10, 3}};
  const Ring inside{{3.5, -1}, {5, -1}, {30.0 / 7.0, 9.0 / 7.0}};
  const auto s =
      segmentsOf(world(box(-20, -20, 20, 20), {target}, {inside}), {{5, 6, -4 * kPi / 9}}, kPi / 3);
  EXPECT_NEAR(seenOf(s, 0), std::sqrt(109.0), kTight);
}

TEST(CameraSweep, CollinearConsecutiveVerticesChangeNothing) {
  // The unit square with a vertex inserted in the middle of every side: as in the first test.
  const Ring square{{0, 0}, {0.5, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0.5, 1}, {0, 1}, {0, 0.5}};
  const auto s = segmentsOf(world(kRoom, {square}), {{0, -5, kPi / 2}}, kPi / 6);
  EXPECT_NEAR(seenBy(s, 0), 1.0, kTight);
  for (const Segment& seg : s) {
    EXPECT_EQ(!seg.visibleBy.empty(), seg.edge <= 1) << "edge " << seg.edge;
  }
}

TEST(CameraSweep, VertexOnAFieldOfViewRayCutsExactlyThere) {
  // Looking up with θ = 45°, the right ray runs at 45° through the corner (1, 1) of the square
  // [1, 2]²: its left side (45° to 63°) is in view, its bottom side (27° to 45°) is not.
  const auto s = segmentsOf(world(kRoom, {box(1, 1, 2, 2)}), {{0, 0, kPi / 2}}, kPi / 4);
  EXPECT_NEAR(seenBy(s, 0), 1.0, 1e-9);
  for (const Segment& seg : s) {
    if (seg.edge == 0) {
      EXPECT_LT(length(seg) * (!seg.visibleBy.empty()), 1e-9);
    }
  }
}

TEST(CameraSweep, FieldOfViewWiderThanAHalfPlaneSeesAllButABackwardGap) {
  // θ = 170° looking up leaves a 20° gap around −90°. The squares east, north and west each
  // show their near side (1); the south one shows the parts of its near side outside the gap,
  // |x| ≥ 2 tan 10°. Total 4 − 4 tan 10°.
  const auto s = segmentsOf(world(kRoom, {box(2, -0.5, 3, 0.5), box(-0.5, 2, 0.5, 3),
                                          box(-3, -0.5, -2, 0.5), box(-0.5, -3, 0.5, -2)}),
                            {{0, 0, kPi / 2}}, kPi * 17 / 18);
  EXPECT_NEAR(seenBy(s, 0), 4.0 - 4.0 * std::tan(kPi / 18), kTight);
  EXPECT_NEAR(seenOf(s, 3), 1.0 - 4.0 * std::tan(kPi / 18), kTight);
}

TEST(CameraSweep, TouchingObjectsHideTheirSharedSide) {
  // Two unit squares side by side. From below, both bottoms (2); the shared side x = 1 is
  // edge-on. From the right, only the right square's right side (1).
  const kinematics::World w = world(kRoom, {box(0, 0, 1, 1), box(1, 0, 2, 1)});
  const auto s = segmentsOf(w, {{1, -3, kPi / 2}, {3, 0.5, kPi}}, kPi / 4);
  EXPECT_NEAR(seenBy(s, 0), 2.0, kTight);
  EXPECT_NEAR(seenBy(s, 1), 1.0, kTight);
  EXPECT_NEAR(seenOf(s, 0), 1.0, kTight);
}

TEST(CameraSweep, ObjectTouchingTheBoundaryShowsOnlyItsInnerSides) {
  // A 2 × 2 target in the corner of the room: seen from (5, 5), its top and right sides (4).
  const auto s =
      segmentsOf(world(box(0, 0, 10, 10), {box(0, 0, 2, 2)}), {{5, 5, -3 * kPi / 4}}, kPi / 4);
  EXPECT_NEAR(seenBy(s, 0), 4.0, kTight);
}

TEST(CameraSweep, ObjectPokingThroughTheBoundaryIsSeenOnlyInside) {
  // The target [−1, 1] × [4, 6] crosses the wall x = 0. From (5, 8), its right side (2) and the
  // part x ∈ [0, 1] of its top side (1); the wall hides the rest.
  const auto s = segmentsOf(world(box(0, 0, 10, 10), {box(-1, 4, 1, 6)}), {{5, 8, kPi}}, kPi / 4);
  EXPECT_NEAR(seenBy(s, 0), 3.0, kTight);
}

TEST(CameraSweep, OverlappingObstacleHidesThePartOfATargetInsideIt) {
  // The obstacle [3, 5] × [−1, 2] covers the right end of the target [0, 4] × [0, 1]: from
  // (2, −3) the target's bottom is seen for x ∈ [0, 3] only.
  const auto s =
      segmentsOf(world(kRoom, {box(0, 0, 4, 1)}, {box(3, -1, 5, 2)}), {{2, -3, kPi / 2}}, kPi / 3);
  EXPECT_NEAR(seenBy(s, 0), 3.0, kTight);
}

TEST(CameraSweep, TargetSharingAnEdgeWithAnObstacleIsSeenThroughIt) {
  // The target [1, 2] × [0, 1] lies inside the obstacle [0, 4] × [0, 2], its bottom on the
  // obstacle's bottom. The open segment to a point of that shared side crosses no edge: seen.
  const auto s =
      segmentsOf(world(kRoom, {box(1, 0, 2, 1)}, {box(0, 0, 4, 2)}), {{1.5, -3, kPi / 2}}, kPi / 4);
  EXPECT_NEAR(seenBy(s, 0), 1.0, kTight);
}

TEST(CameraSweep, TargetSideLyingOnTheBoundaryWallIsSeenFromInside) {
  // The target [2, 4] × [−1, 0] sits outside the room with its top side on the wall y = 0: the
  // wall and the side coincide (in opposite directions), and the side is seen.
  const auto s =
      segmentsOf(world(box(0, 0, 10, 10), {box(2, -1, 4, 0)}), {{3, 5, -kPi / 2}}, kPi / 4);
  EXPECT_NEAR(seenBy(s, 0), 2.0, kTight);
}

TEST(CameraSweep, CameraAFewNanometresFromAnEdgeSeesItGrazing) {
  // 1e-9 below the bottom side's midpoint, looking along it (θ = 60°): the right half of the
  // side is in view, all but its first 1e-9 / tan 60° (the right side faces away).
  const kinematics::World w = world(kRoom, {box(0, 0, 1, 1)});
  const auto s = segmentsOf(w, {{0.5, -1e-9, 0}}, kPi / 3);
  EXPECT_NEAR(seenBy(s, 0), 0.5 - 1e-9 / std::tan(kPi / 3), 1e-12);
}

TEST(CameraSweep, CameraOnAnEdgeSeesItEdgeOnAndOnlyTheFreeSide) {
  // On the bottom side exactly, or closer than ε = 1e-12 · 20: the side is edge-on.
  const kinematics::World w = world(kRoom, {box(0, 0, 1, 1), box(0, -4, 1, -3)});
  for (const double y : {0.0, -1e-13, 1e-13}) {
    const auto s = segmentsOf(w, {{0.5, y, 0}, {0.5, y, -kPi / 2}, {0.5, y, kPi / 2}}, kPi / 3);
    EXPECT_NEAR(seenBy(s, 0), 0.0, kTight) << y;
    // Looking down: the top side of the lower square, (0, −3) to (1, −3), all in view.
    EXPECT_NEAR(seenBy(s, 1), 1.0, kTight) << y;
    // Looking up into the square it stands on: nothing.
    EXPECT_NEAR(seenBy(s, 2), 0.0, kTight) << y;
  }
}

TEST(CameraSweep, CameraOnAnObstacleEdgeSeesOnlyTheFreeSide) {
  // On the top side of the obstacle [0, 2]²: the target above is seen (its bottom, 2), the one
  // below the obstacle is not, whatever the field of view.
  const kinematics::World w = world(kRoom, {box(0, 4, 2, 5), box(0, -3, 2, -1)}, {box(0, 0, 2, 2)});
  const auto s = segmentsOf(w, {{1, 2, kPi / 2}, {1, 2, -kPi / 2}}, kPi * 0.9);
  EXPECT_NEAR(seenOf(s, 0), 2.0, kTight);
  EXPECT_NEAR(seenOf(s, 1), 0.0, kTight);
  // Looking down, θ = 162° leaves an upward gap of ±18°: the target above shows its bottom
  // side outside |x − 1| < 2 tan 18°.
  EXPECT_NEAR(seenBy(s, 1), 2.0 - 4.0 * std::tan(0.1 * kPi), kTight);
}

TEST(CameraSweep, CameraOnABoundaryVertexSeesTheInterior) {
  // In the corner (0, 0) of the room, looking diagonally in: the target's left and bottom
  // sides (2). Looking out: nothing.
  const kinematics::World w = world(box(0, 0, 10, 10), {box(4, 4, 5, 5)});
  const auto s = segmentsOf(w, {{0, 0, kPi / 4}, {0, 0, -3 * kPi / 4}}, kPi / 4);
  EXPECT_NEAR(seenBy(s, 0), 2.0, kTight);
  EXPECT_NEAR(seenBy(s, 1), 0.0, kTight);
}

TEST(CameraSweep, CameraOnATargetVertexSeesItsAdjacentSidesEdgeOn) {
  // On the corner (1, 1) of the unit square, looking away from it with a half-plane of view:
  // none of the square, but the left and bottom sides of [2, 3]² (2).
  const auto s =
      segmentsOf(world(kRoom, {box(0, 0, 1, 1), box(2, 2, 3, 3)}), {{1, 1, kPi / 4}}, kPi / 2);
  EXPECT_NEAR(seenOf(s, 0), 0.0, kTight);
  EXPECT_NEAR(seenOf(s, 1), 2.0, kTight);
}

TEST(CameraSweep, NonConvexBoundaryPocketHidesATarget) {
  // A U-shaped room; the target sits in the left arm. From the left arm's floor it shows its
  // bottom side (1); from the right arm the pocket's walls hide it.
  const Ring u{{0, 0}, {10, 0}, {10, 10}, {7, 10}, {7, 3}, {3, 3}, {3, 10}, {0, 10}};
  const double towardTarget = std::atan2(4.5, -7.0);
  const auto s = segmentsOf(world(u, {box(1, 6, 2, 7)}),
                            {{1.5, 1.5, kPi / 2}, {8.5, 1.5, towardTarget}}, kPi / 6);
  EXPECT_NEAR(seenBy(s, 0), 1.0, kTight);
  EXPECT_NEAR(seenBy(s, 1), 0.0, kTight);
}

TEST(CameraSweep, CameraStrictlyInsideAnObjectSeesNothing) {
  const kinematics::World w =
      world(kRoom, {box(0, 0, 4, 4), box(6, 0, 7, 1)}, {box(-5, -5, -3, -3)});
  const auto s = segmentsOf(w, {{2, 2, 0}, {-4, -4, kPi / 4}}, kPi * 0.99);
  EXPECT_EQ(seenByAnyone(s), 0.0);
}

TEST(CameraSweep, CameraStrictlyOutsideTheBoundarySeesNothing) {
  const auto s = segmentsOf(world(box(0, 0, 10, 10), {box(4, 4, 5, 5)}),
                            {{-1, 4.5, 0}, {20, 4.5, kPi}}, kPi / 4);
  EXPECT_EQ(seenByAnyone(s), 0.0);
}

TEST(CameraSweep, SegmentsTileEveryTargetBoundaryWithMasksOfAllCameras) {
  // Two cameras 1 below a 4 × 1 target. With θ = 30° each sees |x − x_j| ≤ tan 30° of the
  // bottom side; with θ = 60° they overlap, and the bottom is cut into the part only camera 0
  // sees, the part both see ({0, 1}, as s7 in the paper's Fig. 1) and the part only camera 1
  // sees.
  const Ring target = box(0, 0, 4, 1);
  const auto s = segmentsOf(world(kRoom, {target}), {{1, -1, kPi / 2}, {3, -1, kPi / 2}}, kPi / 6);
  double total = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    total += length(s[i]);
    if (i > 0 && s[i].edge == s[i - 1].edge) {
      EXPECT_EQ(s[i].a, s[i - 1].b);  // contiguous
    }
  }
  EXPECT_NEAR(total, 10.0, kTight);
  std::vector<std::uint64_t> bottom;
  for (const Segment& seg : s) {
    if (seg.edge == 0) bottom.push_back(seg.visibleBy.word(0));
  }
  EXPECT_EQ(bottom, (std::vector<std::uint64_t>{0, 1, 0, 2, 0}));
  EXPECT_NEAR(seenBy(s, 0), 2.0 * std::tan(kPi / 6), kTight);
  const auto wide =
      segmentsOf(world(kRoom, {target}), {{1, -1, kPi / 2}, {3, -1, kPi / 2}}, kPi / 3);
  bottom.clear();
  for (const Segment& seg : wide) {
    if (seg.edge == 0) bottom.push_back(seg.visibleBy.word(0));
  }
  EXPECT_EQ(bottom, (std::vector<std::uint64_t>{1, 3, 2}));
  EXPECT_NEAR(seenByAnyone(wide), 4.0, kTight);
}

TEST(CameraSweep, SameInputGivesBitIdenticalOutput) {
  const kinematics::World w = world(kRoom, {box(0, 0, 1, 1), box(2, 2, 3, 4)}, {box(-3, 1, -2, 5)});
  const std::vector<Pose> cameras{{0.3, -4.1, 1.2}, {5.5, 5.5, -2.0}, {-6, 0.1, 0.1}};
  EXPECT_EQ(segmentsOf(w, cameras, 1.1).size(), segmentsOf(w, cameras, 1.1).size());
  const auto a = segmentsOf(w, cameras, 1.1), b = segmentsOf(w, cameras, 1.1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].a, b[i].a);
    EXPECT_EQ(a[i].b, b[i].b);
    EXPECT_EQ(a[i].visibleBy, b[i].visibleBy);
  }
}

TEST(CameraSweep, AHundredAndTwentyEightCamerasAreTheLimit) {
  const kinematics::World w = world(kRoom, {box(0, 0, 1, 1)});
  std::vector<Pose> cameras(128, Pose{0.5, -5, kPi / 2});
  const auto s = segmentsOf(w, cameras, kPi / 6);
  EXPECT_EQ(s.front().visibleBy.size(), 128u);
  EXPECT_TRUE(s.front().visibleBy.contains(127));
  cameras.push_back(cameras.back());
  EXPECT_THROW(segmentsOf(w, cameras, kPi / 6), std::invalid_argument);
}

TEST(CameraSweep, FieldOfViewOutsideTheOpenHalfTurnIsRejected) {
  const kinematics::World w = world(kRoom, {box(0, 0, 1, 1)});
  for (const double theta : {0.0, -0.1, kPi, 4.0, std::nan("")}) {
    EXPECT_THROW(segmentsOf(w, {{0, -5, 0}}, theta), std::invalid_argument) << theta;
  }
  EXPECT_THROW(segmentsOf(w, {{std::nan(""), -5, 0}}, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace camcov::visibility
