// createSegments (Algorithm 1, line 1): the shared arrangement of one World's edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "geometry/predicates.h"
#include "support/small_worlds.h"
#include "visibility/occluders.h"

namespace camcov::visibility {
namespace {

using camcov::testing::box;
using camcov::testing::world;
using geometry::Ring;
using geometry::Vec2;

std::vector<Vec2> chainVertices(const Occluders& o, std::size_t chain) {
  const Chain& c = o.chains()[chain];
  return {o.vertices().begin() + c.first, o.vertices().begin() + c.first + c.count};
}

TEST(Occluders, DisjointObjectsAreNotSplit) {
  const Occluders o(world(box(0, 0, 10, 10), {box(1, 1, 2, 2)}, {box(5, 5, 6, 7)}));
  EXPECT_EQ(o.pieceCount(), 12u);
  ASSERT_EQ(o.chains().size(), 3u);
  EXPECT_EQ(o.chains()[0].kind, RingKind::Boundary);
  EXPECT_FALSE(o.chains()[0].solidOnLeft);  // the boundary's outside is on its right
  EXPECT_EQ(o.chains()[1].kind, RingKind::Obstacle);
  EXPECT_TRUE(o.chains()[1].solidOnLeft);
  EXPECT_EQ(o.chains()[2].kind, RingKind::Target);
}

TEST(Occluders, CrossingObjectsAreSplitAtASharedVertex) {
  // The obstacle [3, 5] × [−1, 1] crosses the target [0, 4] × [0, 2] at (3, 0) and (4, 1).
  const Occluders o(world(box(-10, -10, 10, 10), {box(0, 0, 4, 2)}, {box(3, -1, 5, 1)}));
  const auto obstacle = chainVertices(o, 1), target = chainVertices(o, 2);
  EXPECT_EQ(obstacle.size(), 6u);
  EXPECT_EQ(target.size(), 6u);
  for (const Vec2 x : {Vec2{3, 0}, Vec2{4, 1}}) {
    EXPECT_NE(std::find(obstacle.begin(), obstacle.end(), x), obstacle.end());
    EXPECT_NE(std::find(target.begin(), target.end(), x), target.end());
  }
}

TEST(Occluders, VertexTouchingAnEdgeSplitsThatEdge) {
  // The triangle's apex (2, 2) lies on the square's top side.
  const Occluders o(world(box(-10, -10, 10, 10), {box(0, 0, 4, 2)}, {{{1, 3}, {2, 2}, {3, 3}}}));
  const auto target = chainVertices(o, 2);
  EXPECT_NE(std::find(target.begin(), target.end(), Vec2{2, 2}), target.end());
  EXPECT_EQ(chainVertices(o, 1).size(), 3u);
}

// The triangle (8, −1), (18, 16), (−1, 2), the obstacle (1, 0), (4, 4.5), (7, 9), (17, 13),
// (0, 7) and the wall x = 16 all cross at (16, 12.6): each pair computes its own crossing,
// a few ulps from the others.
const kinematics::World kThreeRingsThroughOnePoint =
    world(box(0, 0, 16, 16), {{{8, -1}, {18, 16}, {-1, 2}}},
          {{{1, 0}, {4, 4.5}, {7, 9}, {17, 13}, {0, 7}}});

TEST(Occluders, EdgesCrossingAtOnePointShareOneVertexThere) {
  const Occluders o(kThreeRingsThroughOnePoint);
  std::vector<Vec2> near;
  for (std::size_t chain = 0; chain < 3; ++chain) {
    int found = 0;
    for (const Vec2 v : chainVertices(o, chain)) {
      if (distance(v, {16, 12.6}) > 1e-9) continue;
      ++found;
      near.push_back(v);
    }
    EXPECT_EQ(found, 1) << "chain " << chain;
  }
  ASSERT_EQ(near.size(), 3u);
  EXPECT_EQ(near[0], near[1]);
  EXPECT_EQ(near[1], near[2]);
}

TEST(Occluders, VertexAnUlpOffAnEdgeStillSplitsIt) {
  // The triangle's apex is (10/3, 1) rounded: an ulp below the quadrilateral's side from
  // (0, 0) to (10, 3), so the triangle does not cross it, but within ε, so it touches that
  // side and splits it.
  const Vec2 apex{10.0 / 3.0, 1.0};
  ASSERT_NE(geometry::orientSign({0, 0}, {10, 3}, apex), 0);
  const Ring side{{0, 0}, {10, 3}, {10, 10}, {0, 10}};
  const Ring below{{2, -2}, {5, -2}, apex};
  const Occluders o(world(box(-20, -20, 20, 20), {side}, {below}));
  const auto target = chainVertices(o, 2);
  EXPECT_NE(std::find(target.begin(), target.end(), apex), target.end());
  EXPECT_EQ(target.size(), 5u);
}

TEST(Occluders, TargetPiecesCoverEveryEdgeOnceFromZeroToOne) {
  const Occluders o(
      world(box(-10, -10, 10, 10), {box(0, 0, 4, 2), box(1, 1, 6, 5)}, {box(3, -1, 5, 1)}));
  std::vector<double> covered(o.targetEdgeCount(), 0.0);
  for (std::uint32_t p = 0; p < o.pieceCount(); ++p) {
    if (o.globalEdge(p) == Occluders::kNoEdge) continue;
    EXPECT_LT(o.t0(p), o.t1(p));
    covered[o.globalEdge(p)] += o.t1(p) - o.t0(p);
  }
  for (const double c : covered)
    EXPECT_NEAR(c, 1.0, 1e-15);
}

TEST(Occluders, EdgesLyingOnEachOtherBecomeTwins) {
  // The target's bottom side lies on the obstacle's (same direction); its top side on the
  // boundary-like wall of a second obstacle's bottom side (opposite direction).
  const Occluders o(
      world(box(-10, -10, 10, 10), {box(1, 0, 2, 1)}, {box(0, 0, 4, 0.5), box(0, 1, 4, 3)}));
  int twins = 0;
  for (std::uint32_t p = 0; p < o.pieceCount(); ++p) {
    if (o.isRepresentative(p)) continue;
    ++twins;
  }
  EXPECT_EQ(twins, 2);
  // Each representative of a twin pair carries the target piece, with its direction.
  int carried = 0;
  for (std::uint32_t p = 0; p < o.pieceCount(); ++p) {
    if (!o.isRepresentative(p)) continue;
    for (const Occluders::Member m : o.targetMembers(p)) {
      if (m.piece == p) continue;
      ++carried;
      const Vec2 a = o.vertices()[m.piece], b = o.vertices()[o.next(m.piece)];
      const Vec2 ra = o.vertices()[p], rb = o.vertices()[o.next(p)];
      EXPECT_EQ(m.reversed ? (a == rb && b == ra) : (a == ra && b == rb), true);
    }
  }
  EXPECT_EQ(carried, 2);
}

TEST(Occluders, RepeatedVerticesAreDroppedButEdgeNumbersKept) {
  // Vertex 1 repeats vertex 0: edge 0 has no length, the bottom side is edge 1.
  const Ring target{{0, 0}, {0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const Occluders o(world(box(-10, -10, 10, 10), {target}));
  EXPECT_EQ(chainVertices(o, 1).size(), 4u);
  EXPECT_EQ(o.targetEdgeCount(), 5u);
  std::vector<std::uint32_t> edges;
  for (std::uint32_t p = o.chains()[1].first; p < o.pieceCount(); ++p)
    edges.push_back(o.globalEdge(p));
  EXPECT_EQ(edges, (std::vector<std::uint32_t>{1, 2, 3, 4}));
}

TEST(Occluders, EveryPieceNamesItsRingAndTheRingEdgeItLiesOn) {
  // The obstacle repeats its first vertex (its edge 0 has no length) and crosses the target
  // at (3, 0) and (4, 1), so some pieces are parts of an edge.
  const Ring obstacle{{3, -1}, {3, -1}, {5, -1}, {5, 1}, {3, 1}};
  const auto w = world(box(-10, -10, 10, 10), {box(0, 0, 4, 2)}, {obstacle});
  const Occluders o(w);
  std::vector<std::uint32_t> obstacleEdges;
  for (std::uint32_t p = 0; p < o.pieceCount(); ++p) {
    const Chain& chain = o.chainOf(p);
    EXPECT_EQ(&chain, &o.chains()[chain.kind == RingKind::Boundary   ? 0
                                  : chain.kind == RingKind::Obstacle ? 1
                                                                     : 2]);
    const Ring& ring = chain.kind == RingKind::Boundary   ? w.boundary
                       : chain.kind == RingKind::Obstacle ? w.obstacles[chain.owner]
                                                          : w.targets[chain.owner];
    const std::uint32_t k = o.ringEdge(p);
    ASSERT_LT(k, ring.size());
    const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
    for (const Vec2 end : {o.vertices()[p], o.vertices()[o.next(p)]}) {
      EXPECT_EQ(orient(a, b, end), 0.0) << "piece " << p;
      EXPECT_LE(dot(end - a, end - b), 0.0) << "piece " << p;  // between a and b
    }
    if (chain.kind == RingKind::Obstacle) obstacleEdges.push_back(k);
  }
  // Edges 1 and 2 (y = −1 and x = 5) are whole; 3 and 4 are split where the target crosses.
  EXPECT_EQ(obstacleEdges, (std::vector<std::uint32_t>{1, 2, 3, 3, 4, 4}));
}

TEST(Occluders, ToleranceScalesWithTheWorld) {
  const Occluders small(world(box(0, 0, 1, 1), {box(0.2, 0.2, 0.4, 0.4)}));
  const Occluders large(world(box(0, 0, 1000, 500), {box(2, 2, 4, 4)}));
  EXPECT_DOUBLE_EQ(small.tolerance(), 1e-12);
  EXPECT_DOUBLE_EQ(large.tolerance(), 1e-9);
}

}  // namespace
}  // namespace camcov::visibility
