// Omnidirectional and field-of-view visibility polygons (the sweep's second output): hand-made
// cases, then random viewpoints checked against the reference's angular decomposition.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include "random_scenes.h"
#include "reference_visibility.h"
#include "support/small_worlds.h"
#include "visibility/occluders.h"
#include "visibility/sweep.h"

namespace camcov::visibility {
namespace {

using camcov::testing::box;
using camcov::testing::world;
using geometry::Ring;
using geometry::Vec2;

constexpr double kPi = std::numbers::pi;

Ring polygonFrom(const kinematics::World& w, Vec2 point) {
  Sweep sweep;
  Ring out;
  sweep.visibilityPolygon(Occluders(w), point, out);
  return out;
}

// The polygon is star-shaped from `point`: walking its vertices turns counter-clockwise around
// the point exactly once, never backwards.
void expectStarShaped(const Ring& polygon, Vec2 point) {
  double turned = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i] - point, b = polygon[(i + 1) % polygon.size()] - point;
    if (a == Vec2{} || b == Vec2{}) continue;  // the point itself is a vertex
    const double step = std::atan2(cross(a, b), dot(a, b));
    EXPECT_GE(step, -1e-9) << "vertex " << i;
    turned += step;
  }
  const bool onPolygon = std::find(polygon.begin(), polygon.end(), point) != polygon.end();
  if (!onPolygon) {
    EXPECT_NEAR(turned, 2.0 * kPi, 1e-9);
  }
}

TEST(VisibilityPolygon, EmptyRoomIsSeenWhole) {
  const Ring p = polygonFrom(world(box(0, 0, 10, 10), {}), {3, 4});
  EXPECT_EQ(p.size(), 4u);
  EXPECT_NEAR(geometry::signedArea(p), 100.0, 1e-12);
}

TEST(VisibilityPolygon, FromABoundaryCornerTheRoomIsSeenWhole) {
  const Ring p = polygonFrom(world(box(0, 0, 10, 10), {}), {0, 0});
  EXPECT_NEAR(geometry::signedArea(p), 100.0, 1e-12);
  expectStarShaped(p, {0, 0});
}

TEST(VisibilityPolygon, AViewpointWithinTheToleranceOfAWallStandsOnIt) {
  // Within ε of the bottom wall the viewpoint stands on it: the wall's far side is blocked at the
  // viewpoint, which becomes a vertex of the polygon. Farther, the room is seen from inside, as
  // from its middle.
  const kinematics::World w = world(box(0, 0, 10, 10), {});
  const double eps = Occluders(w).tolerance();
  for (const double height : {0.5 * eps, 0.99 * eps}) {
    const Ring p = polygonFrom(w, {5, height});
    EXPECT_NE(std::find(p.begin(), p.end(), Vec2{5, height}), p.end()) << height / eps;
  }
  for (const double height : {1.5 * eps, 2.5 * eps, 1.0}) {
    const Ring p = polygonFrom(w, {5, height});
    EXPECT_EQ(p.size(), 4u) << height / eps;
    EXPECT_NEAR(geometry::signedArea(p), 100.0, 1e-12) << height / eps;
  }
}

TEST(VisibilityPolygon, FromATargetEdgeOnlyTheFreeHalfPlaneIsSeen) {
  // q1 on the top side of the target [4, 6]²: the half-plane y ≥ 6 of the room, 10 × 4, with
  // q1 itself a vertex of the polygon.
  const kinematics::World w = world(box(0, 0, 10, 10), {box(4, 4, 6, 6)});
  const Ring p = polygonFrom(w, {5, 6});
  EXPECT_NEAR(geometry::signedArea(p), 40.0, 1e-12);
  EXPECT_NE(std::find(p.begin(), p.end(), Vec2{5, 6}), p.end());
  expectStarShaped(p, {5, 6});
}

TEST(VisibilityPolygon, FromATargetCornerTheTargetQuadrantIsBlocked) {
  // At the corner (6, 6) of the target [4, 6]² the quadrant x < 6, y < 6 is the target's side:
  // the rest of the room, 100 − 36, is seen.
  const Ring p = polygonFrom(world(box(0, 0, 10, 10), {box(4, 4, 6, 6)}), {6, 6});
  EXPECT_NEAR(geometry::signedArea(p), 64.0, 1e-12);
}

TEST(VisibilityPolygon, ObstacleCastsItsShadow) {
  // From (5, 1) the obstacle [4, 6] × [4, 5] shows its bottom corners as its silhouette; the
  // rays through (4, 4) and (6, 4) reach the wall y = 10 at x = 2 and 8. Obstacle and shadow
  // form the trapezoid with parallel sides 2 and 6, height 6: 24. Seen: 100 − 24.
  const Ring p = polygonFrom(world(box(0, 0, 10, 10), {}, {box(4, 4, 6, 5)}), {5, 1});
  EXPECT_NEAR(geometry::signedArea(p), 76.0, 1e-12);
  expectStarShaped(p, {5, 1});
}

TEST(VisibilityPolygon, InsideAnObjectOrOutsideTheBoundaryIsEmpty) {
  const kinematics::World w = world(box(0, 0, 10, 10), {box(4, 4, 6, 6)});
  EXPECT_TRUE(polygonFrom(w, {5, 5}).empty());
  EXPECT_TRUE(polygonFrom(w, {11, 5}).empty());
}

TEST(VisibilityPolygon, FieldOfViewPolygonIsTheViewWedge) {
  // From the room's centre looking +x with θ = 45°: the triangle (5, 5), (10, 0), (10, 10).
  Sweep sweep;
  Ring out;
  const kinematics::World w = world(box(0, 0, 10, 10), {});
  sweep.fieldOfViewPolygon(Occluders(w), {5, 5, 0}, kPi / 4, out);
  EXPECT_NEAR(geometry::signedArea(out), 25.0, 1e-12);
  // And a half-plane of view leaves half the room.
  sweep.fieldOfViewPolygon(Occluders(w), {5, 5, kPi / 2}, kPi / 2, out);
  EXPECT_NEAR(geometry::signedArea(out), 50.0, 1e-12);
}

TEST(VisibilityPolygon, RandomViewpointsAgreeWithTheReference) {
  // Area to 1e-6 relative; every vertex visible from the point; star-shaped, counter-clockwise.
  const char* env = std::getenv("CAMCOV_VISIBILITY_CASES");
  const std::uint64_t count = env != nullptr ? std::stoull(env) : 10000;
  Sweep sweep;
  Occluders occluders;
  Ring polygon;
  int failures = 0;
  for (std::uint64_t index = 0; index < count && failures < 5; ++index) {
    const testing::Case c = testing::randomCase(77, index);
    testing::Random random(index);
    const Vec2 point = testing::randomViewpoint(random, c.world);
    occluders.build(c.world);
    sweep.visibilityPolygon(occluders, point, polygon);
    const double want = reference::visibleArea(c.world, point);
    const double got = polygon.size() < 3 ? 0.0 : geometry::signedArea(polygon);
    const double tol = 1e-6 * want + 1e-9 * occluders.extent() * occluders.extent();
    bool ok = std::abs(got - want) <= tol;
    for (const Vec2 v : polygon) {
      ok = ok && reference::clearLine(c.world, point, v, 1e-9 * occluders.extent());
    }
    if (!ok) {
      ++failures;
      ADD_FAILURE() << "case " << index << " point " << point.x << ' ' << point.y << ": area "
                    << got << " vs " << want << '\n'
                    << testing::describe(c);
    }
    if (polygon.size() >= 3) expectStarShaped(polygon, point);
  }
}

}  // namespace
}  // namespace camcov::visibility
