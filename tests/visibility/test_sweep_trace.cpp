// Sweep::trace: the camera sweep recorded event by event. Expected events, rays and front
// edges are worked out from the geometry by hand (in the comments) or by exact integer
// arithmetic here, never read back from the sweep's own tables.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "random_scenes.h"
#include "support/small_worlds.h"
#include "visibility/sweep.h"

namespace camcov::visibility {
namespace {

using camcov::testing::box;
using camcov::testing::world;
using geometry::Pose;
using geometry::Ring;
using geometry::Vec2;
using Kind = TracedEvent::Kind;

constexpr double kPi = std::numbers::pi;

SweepTrace traceOf(const kinematics::World& w, const Pose& camera, double halfFov) {
  Sweep sweep;
  SweepTrace trace;
  sweep.trace(Occluders(w), camera, halfFov, trace);
  return trace;
}

// Vertex events a camera strictly inside the free space must see: one per ring vertex with at
// least one of its two edges off every line through the camera (an edge on such a line
// subtends no angle). Exact for the integer coordinates used here.
std::size_t expectedVertexEvents(const kinematics::World& w, Vec2 camera) {
  std::size_t n = 0;
  const auto count = [&](const Ring& ring) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2 before = ring[(k + ring.size() - 1) % ring.size()], v = ring[k],
                 after = ring[(k + 1) % ring.size()];
      if (orient(before, v, camera) != 0.0 || orient(v, after, camera) != 0.0) ++n;
    }
  };
  count(w.boundary);
  for (const Ring& r : w.obstacles)
    count(r);
  for (const Ring& r : w.targets)
    count(r);
  return n;
}

// Distinct rays from the camera through those vertices: two directions are one ray when they
// are parallel and point the same way.
std::size_t expectedVertexRays(const kinematics::World& w, Vec2 camera) {
  std::vector<Vec2> directions;
  const auto add = [&](const Ring& ring) {
    for (const Vec2 v : ring) {
      const Vec2 d = v - camera;
      bool seen = false;
      for (const Vec2 e : directions)
        seen = seen || (cross(d, e) == 0.0 && dot(d, e) > 0.0);
      if (!seen) directions.push_back(d);
    }
  };
  add(w.boundary);
  for (const Ring& r : w.obstacles)
    add(r);
  for (const Ring& r : w.targets)
    add(r);
  return directions.size();
}

bool isEdge(const TracedEdge& e, RingKind ring, std::uint32_t owner, std::uint32_t edge) {
  return e.kind == TracedEdge::Kind::Edge && e.ring == ring && e.owner == owner && e.edge == edge;
}

const TracedEvent* eventAt(const SweepTrace& trace, Vec2 point) {
  for (const TracedEvent& e : trace.events) {
    if (e.kind == Kind::Vertex && e.point == point) return &e;
  }
  return nullptr;
}

// A square room, one obstacle and one target; the camera at (0, −1) looks up with θ = 80°, so
// its view runs from 10° to 170°. The obstacle's bottom side lies on the camera's line y = −1:
// its corners (2, −1) and (4, −1) are on one ray. The target [−6, −4] × [2, 4] shows its right
// and bottom sides: the right side (edge 1) is in front from its top corner (−4, 4), at
// 128.7°, to (−4, 2), at 143.1°, where the bottom side (edge 0) takes over until (−6, 2).
class SweepTraceInARoom : public ::testing::Test {
 protected:
  const kinematics::World world_ =
      world(box(-10, -10, 10, 10), {box(-6, 2, -4, 4)}, {box(2, -1, 4, 1)});
  const Pose camera_{0, -1, kPi / 2};
  const double halfFov_ = kPi * 4 / 9;
  const SweepTrace trace_ = traceOf(world_, camera_, halfFov_);
};

TEST_F(SweepTraceInARoom, VisitsOneEventPerVertexAndTwoForTheFieldOfView) {
  EXPECT_FALSE(trace_.blind);
  EXPECT_EQ(trace_.events.size(), expectedVertexEvents(world_, camera_.position()) + 2);
  EXPECT_EQ(trace_.events.size(), 14u);  // 4 + 4 + 4 vertices and the two rays
  int fov = 0;
  for (const TracedEvent& e : trace_.events)
    fov += e.kind == Kind::FovEnter || e.kind == Kind::FovLeave;
  EXPECT_EQ(fov, 2);
}

TEST_F(SweepTraceInARoom, EventsComeInCounterClockwiseOrderFromThePlusXAxis) {
  for (std::size_t i = 0; i < trace_.events.size(); ++i) {
    const TracedEvent& e = trace_.events[i];
    EXPECT_GE(e.angle, 0.0);
    EXPECT_LT(e.angle, 2 * kPi);
    if (e.kind == Kind::Vertex) {
      const Vec2 d = e.point - camera_.position();
      EXPECT_DOUBLE_EQ(e.angle, std::fmod(std::atan2(d.y, d.x) + 2 * kPi, 2 * kPi)) << i;
    }
    if (i > 0) {
      EXPECT_LE(trace_.events[i - 1].angle, e.angle) << i;
    }
  }
  EXPECT_EQ(trace_.events.front().kind, Kind::Vertex);  // the obstacle's corners at 0°
  EXPECT_EQ(trace_.events.front().angle, 0.0);
}

TEST_F(SweepTraceInARoom, VerticesOnOneRayShareItAndItsFrontEdge) {
  // Rays: every vertex direction once, the obstacle's two bottom corners together, plus the
  // two field-of-view rays (10° and 170° pass through no vertex).
  EXPECT_EQ(trace_.events.back().ray + 1, expectedVertexRays(world_, camera_.position()) + 2);
  EXPECT_EQ(trace_.events.back().ray + 1, 13u);
  const TracedEvent* near = eventAt(trace_, {2, -1});
  const TracedEvent* far = eventAt(trace_, {4, -1});
  ASSERT_TRUE(near && far);
  EXPECT_EQ(near->ray, 0u);
  EXPECT_EQ(far->ray, 0u);
  // Just above the ray, the obstacle's left side (edge 3, from (2, 1) to (2, −1)) is in front.
  EXPECT_TRUE(isEdge(near->frontAfter, RingKind::Obstacle, 0, 3));
  EXPECT_TRUE(isEdge(far->frontAfter, RingKind::Obstacle, 0, 3));
  for (std::size_t i = 1; i < trace_.events.size(); ++i) {
    const TracedEvent &a = trace_.events[i - 1], &b = trace_.events[i];
    EXPECT_LE(b.ray - a.ray, 1u);  // numbered consecutively
    if (a.ray == b.ray) {
      EXPECT_EQ(a.angle, b.angle);
      EXPECT_EQ(a.frontAfter.piece, b.frontAfter.piece);
    }
  }
}

TEST_F(SweepTraceInARoom, FrontAfterEachTargetCornerIsTheTargetEdgeSeenNext) {
  const TracedEvent* top = eventAt(trace_, {-4, 4});
  const TracedEvent* hidden = eventAt(trace_, {-6, 4});
  const TracedEvent* bottom = eventAt(trace_, {-4, 2});
  const TracedEvent* last = eventAt(trace_, {-6, 2});
  ASSERT_TRUE(top && hidden && bottom && last);
  EXPECT_TRUE(isEdge(top->frontAfter, RingKind::Target, 0, 1));
  EXPECT_EQ(top->hitAfter, (Vec2{-4, 4}));
  EXPECT_EQ(top->inserted, 2);  // the right and the top side start there
  EXPECT_EQ(top->removed, 0);
  EXPECT_TRUE(isEdge(hidden->frontAfter, RingKind::Target, 0, 1));  // behind the right side
  EXPECT_TRUE(isEdge(bottom->frontAfter, RingKind::Target, 0, 0));
  EXPECT_EQ(bottom->inserted, 1);
  EXPECT_EQ(bottom->removed, 1);
  EXPECT_EQ(last->frontAfter.ring, RingKind::Boundary);
  EXPECT_EQ(last->removed, 2);
  // The front edges seen in view are exactly the target edges segments() finds seen.
  Sweep sweep;
  std::vector<Segment> segments;
  sweep.segments(Occluders(world_), std::vector<Pose>{camera_}, halfFov_, segments);
  for (const Segment& s : segments) {
    EXPECT_EQ(!s.visibleBy.empty(), s.edge <= 1) << "edge " << s.edge;
  }
}

TEST_F(SweepTraceInARoom, FieldOfViewRaysEndOnTheirFrontEdge) {
  for (const TracedEvent& e : trace_.events) {
    if (e.kind == Kind::FovEnter) {
      // At 10° the obstacle's left side x = 2 (from y = −1 to 1) is in front.
      EXPECT_NEAR(e.angle, kPi / 18, 1e-15);
      EXPECT_TRUE(e.inFovAfter);
      EXPECT_TRUE(isEdge(e.frontAfter, RingKind::Obstacle, 0, 3));
      EXPECT_NEAR(e.point.x, 2.0, 1e-12);
      EXPECT_NEAR(e.point.y, -1.0 + 2.0 * std::tan(kPi / 18), 1e-12);
    }
    if (e.kind == Kind::FovLeave) {
      EXPECT_NEAR(e.angle, kPi * 17 / 18, 1e-15);
      EXPECT_FALSE(e.inFovAfter);
      EXPECT_TRUE(isEdge(e.frontAfter, RingKind::Boundary, 0, 3));  // the left wall, x = −10
      EXPECT_NEAR(e.point.x, -10.0, 1e-12);
    }
  }
  EXPECT_FALSE(trace_.inFovBefore);
  EXPECT_TRUE(isEdge(trace_.frontBefore, RingKind::Boundary, 0, 1));
}

TEST(SweepTrace, CameraOnACornerSeesWedgeEventsOnTheRaysOfItsWalls) {
  // From the room's corner (−10, −10) the outside is a blocked wedge from 90° round to 0°. The
  // wedge's end shares the ray at 0° with the vertex (10, −10), its start the ray at 90° with
  // (−10, 10); the corner itself is no event. Looking at 45° with θ = 60°, the view runs from
  // 345° to 105°. Events: 0°, 0°, 45°, 90°, 90°, 105°, 345° on five rays.
  const SweepTrace t = traceOf(world(box(-10, -10, 10, 10), {}, {}), {-10, -10, kPi / 4}, kPi / 3);
  ASSERT_EQ(t.events.size(), 7u);
  const std::vector<double> angles{0, 0, 45, 90, 90, 105, 345};
  const std::vector<std::uint32_t> rays{0, 0, 1, 2, 2, 3, 4};
  for (std::size_t i = 0; i < angles.size(); ++i) {
    EXPECT_NEAR(geometry::radToDeg(t.events[i].angle), angles[i], 1e-12) << i;
    EXPECT_EQ(t.events[i].ray, rays[i]) << i;
  }
  const auto kindOf = [&t](std::size_t i) { return t.events[i].kind; };
  EXPECT_EQ(kindOf(0) == Kind::WedgeEnd, kindOf(1) == Kind::Vertex);
  EXPECT_EQ(kindOf(3) == Kind::WedgeStart, kindOf(4) == Kind::Vertex);
  EXPECT_NE(kindOf(0), kindOf(1));
  EXPECT_NE(kindOf(3), kindOf(4));
  EXPECT_EQ(kindOf(5), Kind::FovLeave);
  EXPECT_EQ(kindOf(6), Kind::FovEnter);
  EXPECT_EQ(t.frontBefore.kind, TracedEdge::Kind::Wedge);
  EXPECT_TRUE(t.inFovBefore);
  EXPECT_TRUE(isEdge(t.events[0].frontAfter, RingKind::Boundary, 0, 1));  // x = 10
  EXPECT_TRUE(isEdge(t.events[2].frontAfter, RingKind::Boundary, 0, 2));  // y = 10
  for (std::size_t i = 3; i < t.events.size(); ++i) {
    EXPECT_EQ(t.events[i].frontAfter.kind, TracedEdge::Kind::Wedge) << i;
    EXPECT_EQ(t.events[i].hitAfter, (Vec2{-10, -10})) << i;
  }
}

TEST(SweepTrace, RayThroughCornersOfTwoTargetsHandsOverToTheFarTarget) {
  // From the origin the ray of slope 1/2 passes through (2, 1), the last corner of the near
  // square counter-clockwise, and (4, 2), the far square's first: one batch, after which the
  // far square's left side (edge 3, from (4, 3) to (4, 2)) is in front.
  const auto w = world(box(-10, -10, 10, 10), {box(2, 0, 3, 1), box(4, 2, 5, 3)}, {});
  const SweepTrace t = traceOf(w, {0, 0, 0}, kPi / 4);
  const TracedEvent* near = eventAt(t, {2, 1});
  const TracedEvent* far = eventAt(t, {4, 2});
  ASSERT_TRUE(near && far);
  EXPECT_EQ(near->ray, far->ray);
  EXPECT_LT(near, far);  // sorted by angle only: the order of the rings in the World
  EXPECT_EQ(near->removed, 2);
  EXPECT_EQ(far->removed, 1);
  EXPECT_EQ(far->inserted, 1);
  EXPECT_TRUE(isEdge(near->frontAfter, RingKind::Target, 1, 3));
  EXPECT_TRUE(isEdge(far->frontAfter, RingKind::Target, 1, 3));
  EXPECT_EQ(far->frontAfter.a, (Vec2{4, 3}));
  EXPECT_EQ(far->frontAfter.b, (Vec2{4, 2}));
}

TEST(SweepTrace, CameraInsideAnObstacleIsBlindAndHasNoEvents) {
  const auto w = world(box(-10, -10, 10, 10), {box(0, 0, 1, 1)}, {box(4, 4, 6, 6)});
  const SweepTrace t = traceOf(w, {5, 5, 0}, kPi / 4);
  EXPECT_TRUE(t.blind);
  EXPECT_TRUE(t.events.empty());
  EXPECT_TRUE(t.fieldOfView.empty());
}

TEST(SweepTrace, RunsTheSameSweepAsTheFieldOfViewPolygon) {
  // On the randomized degenerate cases: the polygon traced is the polygon drawn, bit for bit,
  // the events are in angular order and the rays numbered consecutively.
  Sweep sweep, traced;
  SweepTrace t;
  Ring polygon;
  for (std::uint64_t index = 0; index < 300; ++index) {
    const testing::Case c = testing::randomCase(2024, index);
    const Occluders occluders(c.world);
    sweep.fieldOfViewPolygon(occluders, c.cameras[0], c.halfFov, polygon);
    traced.trace(occluders, c.cameras[0], c.halfFov, t);
    ASSERT_EQ(t.fieldOfView, polygon) << testing::describe(c);
    for (std::size_t i = 1; i < t.events.size(); ++i) {
      const TracedEvent &a = t.events[i - 1], &b = t.events[i];
      ASSERT_LE(a.angle, b.angle + 1e-12) << i << "\n" << testing::describe(c);
      ASSERT_LE(b.ray - a.ray, 1u) << testing::describe(c);
    }
  }
}

}  // namespace
}  // namespace camcov::visibility
