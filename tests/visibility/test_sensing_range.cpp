// A camera with a sensing range (scene::Lens::range) sees nothing beyond it: hand-computed
// cases, the explanation the explorer gives, the drawn field of view, and on seeded random
// configurations the sweep with a range against the sweep without one cut to the circle by
// this test's own search (not the lens's formula).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "random_scenes.h"
#include "support/small_worlds.h"
#include "visibility/sweep.h"
#include "visibility/unseen_reason.h"

namespace camcov::visibility {
namespace {

using camcov::testing::box;
using camcov::testing::rangedLens;
using camcov::testing::world;
using geometry::Pose;
using geometry::Vec2;

constexpr double kPi = std::numbers::pi;

double seenLength(const kinematics::World& w, const Pose& camera, const scene::Lens& lens) {
  Sweep sweep;
  std::vector<Segment> out;
  sweep.segments(Occluders(w), std::vector<Pose>{camera}, lens, out);
  double sum = 0.0;
  for (const Segment& s : out)
    sum += !s.visibleBy.empty() ? length(s) : 0.0;
  return sum;
}

// A 2 m square whose near edge is x = 3, |y| ≤ 1, in front of a camera at the origin facing +x
// with θ = 60°: unlimited, it sees that edge (2 m) only.
kinematics::World squareAhead() {
  return world(box(-10, -10, 10, 10), {box(3, -1, 5, 1)});
}

TEST(SensingRange, SeesOnlyTheChordOfTheNearEdgeWithinRange) {
  const auto w = squareAhead();
  const Pose camera{0, 0, 0};
  EXPECT_NEAR(seenLength(w, camera, kPi / 3), 2.0, 1e-12);
  // r² = 9 + y²: |y| ≤ 0.5 for r = √9.25, so 1 m of the edge.
  EXPECT_NEAR(seenLength(w, camera, rangedLens(kPi / 3, std::sqrt(9.25))), 1.0, 1e-12);
  // r = √10 reaches the corners: the whole edge; beyond, no more (the rest faces away).
  EXPECT_NEAR(seenLength(w, camera, rangedLens(kPi / 3, std::sqrt(10.0))), 2.0, 1e-12);
  EXPECT_NEAR(seenLength(w, camera, rangedLens(kPi / 3, 50.0)), 2.0, 1e-12);
  // Short of the edge, or just touching it at one point: nothing.
  EXPECT_EQ(seenLength(w, camera, rangedLens(kPi / 3, 2.9)), 0.0);
  EXPECT_EQ(seenLength(w, camera, rangedLens(kPi / 3, 3.0)), 0.0);
}

TEST(SensingRange, ARangeThatIsNotPositiveIsRefusedNotReadAsUnlimited) {
  const auto w = squareAhead();
  for (const double bad : {0.0, -1.0, std::nan("")})
    EXPECT_THROW(seenLength(w, {0, 0, 0}, rangedLens(kPi / 3, bad)), std::invalid_argument) << bad;
}

TEST(SensingRange, TheSegmentsOfSAreCutAtTheCircle) {
  const auto w = squareAhead();
  Sweep sweep;
  std::vector<Segment> out;
  sweep.segments(Occluders(w), std::vector<Pose>{{0, 0, 0}}, rangedLens(kPi / 3, std::sqrt(9.25)),
                 out);
  int seen = 0;
  for (const Segment& s : out) {
    if (s.visibleBy.empty()) continue;
    ++seen;
    EXPECT_NEAR(std::min(s.a.y, s.b.y), -0.5, 1e-12);
    EXPECT_NEAR(std::max(s.a.y, s.b.y), 0.5, 1e-12);
    EXPECT_NEAR(s.a.x, 3.0, 1e-12);
  }
  EXPECT_EQ(seen, 1);
}

TEST(SensingRange, WhatIsBeyondTheRangeIsOutsideTheFieldOfView) {
  const auto w = squareAhead();
  const auto& ring = w.targets[0];
  // The near edge x = 3 is edge 3 of box(3, −1, 5, 1) (counter-clockwise from (3, −1)).
  const Segment nearEdge{ring[3], ring[0], 0, 3, {}};
  EXPECT_EQ(whyUnseen(w, {0, 0, 0}, kPi / 3, nearEdge).kind, UnseenKind::InSight);
  EXPECT_EQ(whyUnseen(w, {0, 0, 0}, rangedLens(kPi / 3, 2.5), nearEdge).kind,
            UnseenKind::OutsideFieldOfView);
}

TEST(SensingRange, TheDrawnFieldOfViewStaysWithinTheCircleAndIsItsSector) {
  // An empty room: the field of view is a wedge; with r = 4 a sector of area θ r².
  const auto w = world(box(-10, -10, 10, 10), {box(8, 8, 9, 9)});
  Sweep sweep;
  geometry::Ring polygon;
  const Pose camera{0, 0, 0.3};
  sweep.fieldOfViewPolygon(Occluders(w), camera, rangedLens(kPi / 4, 4.0), polygon);
  ASSERT_GE(polygon.size(), 3u);
  for (const Vec2 v : polygon)
    EXPECT_LE(geometry::distance(v, camera.position()), 4.0 + 1e-12);
  // The chords of 2° steps leave out (1 − sin(2°)/(2°·1)) of each slice: under 0.03 %.
  EXPECT_NEAR(geometry::signedArea(polygon), kPi / 4 * 16.0, 3e-4 * kPi / 4 * 16.0);
  // A range longer than the room: the wedge as without one.
  geometry::Ring unlimited, far;
  sweep.fieldOfViewPolygon(Occluders(w), camera, kPi / 4, unlimited);
  sweep.fieldOfViewPolygon(Occluders(w), camera, rangedLens(kPi / 4, 100.0), far);
  EXPECT_EQ(far, unlimited);
}

// The part of segment [a, b] within r of p, found by this test's own search: the distance is
// convex along the segment, so its minimum by ternary search, then each crossing by bisection.
double lengthWithin(Vec2 p, Vec2 a, Vec2 b, double r) {
  const auto d = [&](double t) { return geometry::distance(p, geometry::lerp(a, b, t)); };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    (d(m1) < d(m2) ? hi : lo) = (d(m1) < d(m2) ? m2 : m1);
  }
  const double nearest = 0.5 * (lo + hi);
  if (d(nearest) > r) return 0.0;
  const auto crossing = [&](double inside, double outside) {
    if (d(outside) <= r) return outside;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (inside + outside);
      (d(mid) <= r ? inside : outside) = mid;
    }
    return inside;
  };
  return (crossing(nearest, 1.0) - crossing(nearest, 0.0)) * geometry::distance(a, b);
}

TEST(SensingRange, OnRandomScenesIsTheUnlimitedViewCutToTheCircle) {
  int checked = 0;
  for (std::uint64_t i = 0; i < 360; ++i) {
    // Every sixth among many objects, where large scenes are culled before the sweep.
    const auto crowd = i % 6 == 5 ? testing::Crowd::Many : testing::Crowd::Few;
    const testing::Case c = testing::randomCase(20261127, i, crowd);
    const Occluders occluders(c.world);
    for (std::size_t j = 0; j < c.cameras.size(); ++j) {
      const Pose& camera = c.cameras[j];
      Sweep sweep;
      std::vector<Segment> unlimited, limited;
      sweep.segments(occluders, std::vector<Pose>{camera}, c.halfFov, unlimited);
      // A range among the distances of what the camera sees, so that it cuts.
      double farthest = 0.0;
      for (const Segment& s : unlimited) {
        if (s.visibleBy.empty()) continue;
        farthest = std::max({farthest, geometry::distance(camera.position(), s.a),
                             geometry::distance(camera.position(), s.b)});
      }
      // A range under a micrometre is below the sweep's tolerance of a camera on an edge.
      if (farthest < 1e-6) continue;
      const double r = farthest * (0.3 + 0.6 * static_cast<double>((i * 7 + j) % 10) / 10.0);
      sweep.segments(occluders, std::vector<Pose>{camera}, rangedLens(c.halfFov, r), limited);
      double want = 0.0, got = 0.0;
      for (const Segment& s : unlimited)
        want += !s.visibleBy.empty() ? lengthWithin(camera.position(), s.a, s.b, r) : 0.0;
      for (const Segment& s : limited) {
        if (s.visibleBy.empty()) continue;
        got += length(s);
        EXPECT_LE(geometry::distance(camera.position(), s.a), r * (1 + 1e-12));
        EXPECT_LE(geometry::distance(camera.position(), s.b), r * (1 + 1e-12));
      }
      EXPECT_NEAR(got, want, 1e-9 * std::max(1.0, want)) << testing::describe(c) << "r " << r;
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
}

}  // namespace
}  // namespace camcov::visibility
