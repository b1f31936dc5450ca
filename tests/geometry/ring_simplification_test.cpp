// Fewer vertices for finely drawn rings (geometry/ring_simplification.h).
#include "geometry/ring_simplification.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/rings.h"
#include "support/splitmix64.h"

namespace camcov::geometry {
namespace {

using camcov::testing::SplitMix64;

// A wobbly disc drawn with n vertices: radius r·(1 + a·sin(k·φ)) plus noise of `noise` metres.
Ring wobblyDisc(int n, double r, double a, int k, double noise, SplitMix64& random) {
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * std::numbers::pi * i / n;
    const double radius = r * (1 + a * std::sin(k * phi)) + random.uniform(-noise, noise);
    ring.push_back(radius * unitVector(phi));
  }
  return ring;
}

// The kept vertices, in order, are vertices of the ring; every vertex of the ring lies within
// the tolerance of the simplified ring, and every kept edge within it of the ring's vertices
// it replaces (the Hausdorff distance, checked at the vertices: both are polylines).
void expectFaithful(const Ring& ring, const std::vector<std::uint8_t>& keep, const Ring& simple,
                    double tolerance) {
  ASSERT_EQ(keep.size(), ring.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (keep[i] == 0) continue;
    ASSERT_LT(k, simple.size());
    EXPECT_EQ(simple[k].x, ring[i].x);
    EXPECT_EQ(simple[k].y, ring[i].y);
    ++k;
  }
  EXPECT_EQ(k, simple.size());
  for (const Vec2 v : ring)
    EXPECT_LE(distanceToBoundary(simple, v), tolerance * (1 + 1e-12)) << v.x << ", " << v.y;
}

TEST(RingSimplification, AFinelyDrawnRingKeepsEveryPointWithinTheTolerance) {
  SplitMix64 random{11};
  int simplified = 0;
  for (int round = 0; round < 200; ++round) {
    const int n = static_cast<int>(random.uniform(20, 3000));
    const double tolerance = std::pow(10.0, random.uniform(-4, -1));
    const Ring ring = wobblyDisc(n, random.uniform(0.5, 5), random.uniform(0, 0.4),
                                 static_cast<int>(random.uniform(1, 9)),
                                 random.uniform(0, 2) * tolerance, random);
    std::vector<std::uint8_t> keep;
    Ring simple;
    if (!simplifiedRing(ring, tolerance, {}, keep, simple)) continue;  // it would fold
    ++simplified;
    expectFaithful(ring, keep, simple, tolerance);
    EXPECT_FALSE(findSelfIntersection(simple).found());
    EXPECT_GT(signedArea(simple), 0.0);
    EXPECT_LT(simple.size(), ring.size());
  }
  // Noisy rings (noise up to twice the tolerance) may keep more than half of their vertices and
  // are refused; the smooth ones are not: most rings are simplified (about three in four).
  EXPECT_GT(simplified, 100) << "wobbly discs drawn this finely lose vertices";
}

TEST(RingSimplification, AFineDiscBecomesOneOfDozensOfVertices) {
  // Radius 2 m, 4,000 vertices, 1 cm: a chord of sagitta 1 cm spans 0.2 rad, so the sweep of
  // the disc needs at least 32 vertices; Douglas–Peucker halves may take up to twice that.
  const Ring disc = camcov::testing::disc({0, 0}, 2.0, 4000);
  std::vector<std::uint8_t> keep;
  Ring simple;
  ASSERT_TRUE(simplifiedRing(disc, 0.01, {}, keep, simple));
  EXPECT_GE(simple.size(), 32u);
  EXPECT_LE(simple.size(), 64u);
  expectFaithful(disc, keep, simple, 0.01);
}

TEST(RingSimplification, CollinearVerticesGoAndCornersStay) {
  // A square whose sides are drawn with 10 vertices each: exactly the 4 corners remain.
  Ring ring;
  const Vec2 corners[4] = {{0, 0}, {3, 0}, {3, 3}, {0, 3}};
  for (int c = 0; c < 4; ++c) {
    for (int i = 0; i < 10; ++i)
      ring.push_back(lerp(corners[c], corners[(c + 1) % 4], i / 10.0));
  }
  std::vector<std::uint8_t> keep;
  Ring simple;
  ASSERT_TRUE(simplifiedRing(ring, 1e-9, {}, keep, simple));
  ASSERT_EQ(simple.size(), 4u);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(keep[10 * c], 1) << "corner " << c;
  }
}

TEST(RingSimplification, ACoarseRingStaysAsItIs) {
  const Ring square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::vector<std::uint8_t> keep;
  Ring simple{{7, 7}};
  EXPECT_FALSE(simplifiedRing(square, 0.01, {}, keep, simple));
  EXPECT_EQ(simple.size(), 1u) << "out is left as it was";
  // A tolerance wider than the ring would leave fewer than 3 vertices: all are kept.
  EXPECT_FALSE(simplifiedRing(square, 10.0, {}, keep, simple));
  EXPECT_EQ(std::count(keep.begin(), keep.end(), 1), 4);
  // Every vertex on one point: nothing to simplify.
  const Ring point{{1, 1}, {1, 1}, {1, 1}, {1, 1}};
  EXPECT_FALSE(simplifiedRing(point, 0.01, {}, keep, simple));
}

TEST(RingSimplification, VerticesThatMustStayStay) {
  SplitMix64 random{5};
  const Ring ring = wobblyDisc(400, 2, 0.1, 3, 0.0, random);
  for (const std::size_t must : {std::size_t{0}, std::size_t{17}, std::size_t{399}}) {
    std::vector<std::uint8_t> mustKeep(ring.size(), 0), keep;
    mustKeep[must] = 1;
    mustKeep[(must + 5) % ring.size()] = 1;  // two close together: a run of 5
    mustKeep[(must + 201) % ring.size()] = 1;
    Ring simple;
    ASSERT_TRUE(simplifiedRing(ring, 0.01, mustKeep, keep, simple));
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (mustKeep[i] != 0) {
        EXPECT_EQ(keep[i], 1) << "vertex " << i;
      }
    }
    expectFaithful(ring, keep, simple, 0.01);
    // A single vertex that must stay is an anchor too.
    std::vector<std::uint8_t> one(ring.size(), 0);
    one[must] = 1;
    ASSERT_TRUE(simplifiedRing(ring, 0.01, one, keep, simple));
    EXPECT_EQ(keep[must], 1);
    expectFaithful(ring, keep, simple, 0.01);
  }
}

TEST(RingSimplification, AChoiceFromAnInstantBeforeIsTakenWhereItStillHolds) {
  SplitMix64 random{9};
  const Ring ring = wobblyDisc(600, 1.5, 0.2, 5, 0.0, random);
  std::vector<std::uint8_t> keep;
  Ring simple;
  ASSERT_TRUE(simplifiedRing(ring, 0.01, {}, keep, simple));
  const std::vector<std::uint8_t> before = keep;
  EXPECT_TRUE(simplificationHolds(ring, 0.01, {}, keep));

  // The ring moved rigidly: the same vertices still do.
  Ring moved = ring;
  transformRing(moved, 0.7, {3, -2});
  ASSERT_TRUE(simplificationHolds(moved, 0.01, {}, keep));
  ASSERT_TRUE(simplifiedRing(moved, 0.01, {}, keep, simple));
  EXPECT_EQ(keep, before);
  expectFaithful(moved, keep, simple, 0.01);

  // A dropped vertex pushed out by twice the tolerance: the choice no longer holds, and the
  // ring is simplified afresh, faithfully.
  std::size_t dropped = 0;
  while (keep[dropped] != 0)
    ++dropped;
  Ring dented = ring;
  dented[dropped] = dented[dropped] * (1 + 0.02 / norm(dented[dropped]));
  EXPECT_FALSE(simplificationHolds(dented, 0.01, {}, keep));
  ASSERT_TRUE(simplifiedRing(dented, 0.01, {}, keep, simple));
  EXPECT_EQ(keep[dropped], 1);
  expectFaithful(dented, keep, simple, 0.01);

  // A vertex that must stay and was dropped, or a choice for another size, does not hold.
  std::vector<std::uint8_t> mustKeep(ring.size(), 0);
  mustKeep[dropped] = 1;
  EXPECT_FALSE(simplificationHolds(ring, 0.01, mustKeep, before));
  EXPECT_FALSE(simplificationHolds(std::span(ring).first(500), 0.01, {}, before));
}

TEST(RingSimplification, ARingThatWouldFoldStaysAsItIs) {
  // The bottom dips 4 mm at x = 5, and a V from the top comes down to 2 mm below y = 0, just
  // above the dip. At 1 cm the dip goes, the bottom runs along y = 0, and the V pokes through it.
  const Ring ring{{0, 0}, {5, -0.004}, {10, 0}, {10, 10}, {6, 10}, {5, -0.002}, {4, 10}, {0, 10}};
  ASSERT_FALSE(findSelfIntersection(ring).found());
  ASSERT_GT(signedArea(ring), 0.0);
  std::vector<std::uint8_t> keep;
  simplificationOf(ring, 0.01, {}, keep);
  EXPECT_EQ(keep[1], 0) << "the dip is within the tolerance";
  Ring bare;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (keep[i] != 0) bare.push_back(ring[i]);
  }
  ASSERT_TRUE(findSelfIntersection(bare).found()) << "the bare choice folds";
  Ring simple;
  EXPECT_FALSE(simplifiedRing(ring, 0.01, {}, keep, simple));
  EXPECT_TRUE(simple.empty());
}

}  // namespace
}  // namespace camcov::geometry
