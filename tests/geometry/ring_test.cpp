#include "geometry/ring.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "geometry/predicates.h"
#include "geometry/same_bits.h"

namespace camcov::geometry {
namespace {

const Ring kUnitSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

TEST(SignedArea, PositiveForCounterClockwiseNegativeForClockwise) {
  EXPECT_DOUBLE_EQ(signedArea(kUnitSquare), 1.0);
  Ring cw(kUnitSquare.rbegin(), kUnitSquare.rend());
  EXPECT_DOUBLE_EQ(signedArea(cw), -1.0);
  EXPECT_DOUBLE_EQ(perimeter(kUnitSquare), 4.0);
}

TEST(NormalizeRing, DropsClosingVertexAndMakesCounterClockwise) {
  Ring ring{{0, 0}, {0, 1}, {1, 1}, {1, 0}, {0, 0}};  // closed, clockwise
  normalizeRing(ring);
  ASSERT_EQ(ring.size(), 4u);
  EXPECT_GT(signedArea(ring), 0.0);
}

TEST(Locate, DistinguishesInsideOutsideAndBoundary) {
  EXPECT_EQ(locate(kUnitSquare, {0.5, 0.5}), Containment::Inside);
  EXPECT_EQ(locate(kUnitSquare, {1.5, 0.5}), Containment::Outside);
  EXPECT_EQ(locate(kUnitSquare, {1.0, 0.5}), Containment::OnBoundary);          // on an edge
  EXPECT_EQ(locate(kUnitSquare, {1.0, 1.0}), Containment::OnBoundary);          // on a vertex
  EXPECT_EQ(locate(kUnitSquare, {1.0 + 1e-12, 0.5}), Containment::OnBoundary);  // within tolerance
}

TEST(Locate, RayThroughVertexCountsOnce) {
  // The horizontal ray from (0, 1) passes exactly through the diamond's vertices (±1, 1)...
  const Ring diamond{{0, 0}, {1, 1}, {0, 2}, {-1, 1}};
  EXPECT_EQ(locate(diamond, {0, 1}), Containment::Inside);
  EXPECT_EQ(locate(diamond, {-2, 1}), Containment::Outside);
  EXPECT_EQ(locate(diamond, {2, 1}), Containment::Outside);
}

TEST(Locate, NonConvexPocketIsOutside) {
  const Ring u{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  EXPECT_EQ(locate(u, {1.5, 2}), Containment::Outside);
  EXPECT_EQ(locate(u, {0.5, 2}), Containment::Inside);
}

TEST(DistanceToSegment, HandlesDegenerateSegmentAndEndpoints) {
  EXPECT_DOUBLE_EQ(distanceToSegment({3, 4}, {0, 0}, {0, 0}), 5.0);
  EXPECT_DOUBLE_EQ(distanceToSegment({0.5, 2}, {0, 0}, {1, 0}), 2.0);
  EXPECT_DOUBLE_EQ(distanceToSegment({4, 4}, {0, 0}, {1, 0}), 5.0);
}

TEST(DistanceToPolygon, IsZeroInsideAndOnBoundary) {
  EXPECT_EQ(distanceToPolygon(kUnitSquare, {0.5, 0.5}), 0.0);
  EXPECT_EQ(distanceToPolygon(kUnitSquare, {1.0, 0.5}), 0.0);
  EXPECT_DOUBLE_EQ(distanceToPolygon(kUnitSquare, {0.5, 3.0}), 2.0);
  EXPECT_DOUBLE_EQ(distanceToBoundary(kUnitSquare, {0.5, 0.5}), 0.5);
}

// The edge-by-edge answers, written out here as the reference that the ring functions, which
// skip blocks of edges on long rings, must give to the bit.
double referenceDistanceToBoundary(const Ring& ring, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ring.size(); ++i)
    best = std::min(best, squaredDistanceToSegment(p, ring[i], ring[(i + 1) % ring.size()]));
  return std::sqrt(best);
}

bool referenceCrossesOddly(const Ring& ring, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[i], b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y))
      inside = !inside;
  }
  return inside;
}

// Star-shaped rings of n vertices around `centre`: radii drawn in [0.2, 1]·r, some vertices
// repeated, some on the line of their neighbours.
Ring starRing(std::size_t n, Vec2 centre, double r, std::mt19937_64& random) {
  std::uniform_real_distribution<double> radius(0.2 * r, r);
  Ring ring;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    if (i % 7 == 3) {
      ring.push_back(ring.back());  // a repeated vertex: a zero-length edge
    } else if (i % 11 == 5) {
      ring.push_back(ring.back() + (ring.back() - ring[ring.size() - 2]));  // collinear
    } else {
      ring.push_back(centre + radius(random) * unitVector(angle));
    }
  }
  return ring;
}

TEST(DistanceToPolygon, LongRingsGiveTheEdgeByEdgeAnswersToTheBit) {
  std::mt19937_64 random(7);
  for (const std::size_t n : {3u, 31u, 32u, 33u, 47u, 48u, 49u, 200u, 4001u}) {
    for (const Vec2 centre : {Vec2{0, 0}, Vec2{3e5, -7e5}}) {
      const Ring ring = starRing(n, centre, 10.0, random);
      std::uniform_real_distribution<double> near(-25.0, 25.0), unit(0.0, 1.0);
      std::vector<Vec2> points;
      for (int k = 0; k < 300; ++k)
        points.push_back(centre + Vec2{near(random), near(random)});
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
        points.push_back(a);                           // on a vertex
        points.push_back(a + unit(random) * (b - a));  // on an edge, as rounding puts it
        points.push_back({centre.x - 30.0, a.y});      // a ray through a vertex
      }
      points.push_back(centre + Vec2{1e4, 1e4});  // far away
      for (const Vec2 p : points) {
        const double reference = referenceDistanceToBoundary(ring, p);
        ASSERT_EQ(distanceToBoundary(ring, p), reference) << n << " at " << p.x << ", " << p.y;
        const bool inside = referenceCrossesOddly(ring, p);
        ASSERT_EQ(distanceToPolygon(ring, p), reference == 0.0 || inside ? 0.0 : reference);
        for (const double tolerance : {0.0, 1e-9, 0.5}) {
          ASSERT_EQ(locate(ring, p, tolerance), reference <= tolerance ? Containment::OnBoundary
                                                : inside               ? Containment::Inside
                                                                       : Containment::Outside);
        }
      }
    }
  }
}

TEST(DistanceToPolygon, LongDegenerateRingsGiveTheEdgeByEdgeAnswers) {
  // Every vertex the same point, and every vertex on one line: no area, no crossing.
  const Ring point(100, Vec2{2, 3});
  Ring line;
  for (int i = 0; i < 100; ++i)
    line.push_back({0.5 * i, 0.0});
  for (const Vec2 p : {Vec2{2, 3}, Vec2{2, 4}, Vec2{-1, 0}, Vec2{10, 0}, Vec2{10, 1}}) {
    for (const Ring* ring : std::array<const Ring*, 2>{&point, &line}) {
      EXPECT_EQ(distanceToBoundary(*ring, p), referenceDistanceToBoundary(*ring, p));
      EXPECT_EQ(distanceToPolygon(*ring, p), referenceDistanceToBoundary(*ring, p));
    }
  }
}

TEST(DistanceBetweenPolygons, ZeroWhenTouchingOverlappingOrNested) {
  Ring shifted;
  placeRing(kUnitSquare, 0.0, {1, 0}, shifted);  // shares the edge x = 1
  EXPECT_EQ(distanceBetweenPolygons(kUnitSquare, shifted), 0.0);
  placeRing(kUnitSquare, 0.0, {0.5, 0.5}, shifted);  // overlaps
  EXPECT_EQ(distanceBetweenPolygons(kUnitSquare, shifted), 0.0);
  const Ring big{{-5, -5}, {5, -5}, {5, 5}, {-5, 5}};
  EXPECT_EQ(distanceBetweenPolygons(big, kUnitSquare), 0.0);  // nested
  placeRing(kUnitSquare, 0.0, {3, 4}, shifted);
  EXPECT_DOUBLE_EQ(distanceBetweenPolygons(kUnitSquare, shifted), std::hypot(2.0, 3.0));
}

TEST(SegmentsIntersect, CoversCrossingTouchingCollinearAndDisjoint) {
  EXPECT_TRUE(segmentsIntersect({0, 0}, {2, 2}, {0, 2}, {2, 0}));   // proper crossing
  EXPECT_TRUE(segmentsIntersect({0, 0}, {2, 0}, {1, 0}, {1, 5}));   // T-junction
  EXPECT_TRUE(segmentsIntersect({0, 0}, {2, 0}, {1, 0}, {3, 0}));   // collinear overlap
  EXPECT_FALSE(segmentsIntersect({0, 0}, {1, 0}, {2, 0}, {3, 0}));  // collinear, apart
  EXPECT_FALSE(segmentsIntersect({0, 0}, {1, 0}, {0, 1}, {1, 1}));  // parallel
}

// Closed segments meet, decided with exact orientations: each pair of ends on both sides of
// (or on) the other's line, and for four collinear points, overlapping spans on one axis.
bool meetExactly(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int d1 = orientSign(c, d, a), d2 = orientSign(c, d, b);
  const int d3 = orientSign(a, b, c), d4 = orientSign(a, b, d);
  if (d1 == 0 && d2 == 0 && d3 == 0 && d4 == 0) {
    const auto overlap = [](double p, double q, double r, double s) {
      return std::max(std::min(p, q), std::min(r, s)) <= std::min(std::max(p, q), std::max(r, s));
    };
    return overlap(a.x, b.x, c.x, d.x) && overlap(a.y, b.y, c.y, d.y);
  }
  return d1 * d2 <= 0 && d3 * d4 <= 0;
}

// Walls parallel to an axis, with ends beside, on and across their lines, on a small grid
// (touching, collinear, zero-length) and at random: as the exact decision says.
TEST(SegmentsIntersect, AgreesWithExactOrientationsAgainstAxisParallelSegments) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> grid(0, 4);
  std::uniform_real_distribution<double> anywhere(-3.0, 7.0);
  int meetings = 0;
  for (int trial = 0; trial < 200000; ++trial) {
    const bool onGrid = trial % 2 == 0;
    const auto point = [&] {
      return onGrid ? Vec2{static_cast<double>(grid(rng)), static_cast<double>(grid(rng))}
                    : Vec2{anywhere(rng), anywhere(rng)};
    };
    const Vec2 a = point(), b = point(), c = point();
    Vec2 d = point();
    if (trial % 4 < 2) {
      d.y = c.y;  // horizontal
    } else {
      d.x = c.x;  // vertical
    }
    const bool meet = meetExactly(a, b, c, d);
    ASSERT_EQ(segmentsIntersect(a, b, c, d), meet)
        << "trial " << trial << ": (" << a.x << ", " << a.y << ")–(" << b.x << ", " << b.y
        << ") and (" << c.x << ", " << c.y << ")–(" << d.x << ", " << d.y << ")";
    meetings += meet;
  }
  EXPECT_GT(meetings, 10000);
}

TEST(FindSelfIntersection, AcceptsSimpleRingsIncludingCollinearVertices) {
  EXPECT_FALSE(findSelfIntersection(kUnitSquare).found());
  const Ring collinear{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_FALSE(findSelfIntersection(collinear).found());
}

TEST(FindSelfIntersection, ReportsBowtieSpikeAndTouchingVertex) {
  const Ring bowtie{{0, 0}, {2, 2}, {2, 0}, {0, 2}};
  EXPECT_TRUE(findSelfIntersection(bowtie).found());
  const Ring spike{{0, 0}, {2, 0}, {1, 0}, {1, 1}};  // edge 1 folds back over edge 0
  EXPECT_TRUE(findSelfIntersection(spike).found());
  // Vertex 3 touches edge 0 at its middle: not simple although no edges cross.
  const Ring touching{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {0, 4}};
  EXPECT_TRUE(findSelfIntersection(touching).found());
}

// The pairwise test on every pair, as findSelfIntersection was before it swept: a reference.
bool selfIntersectsByEveryPair(const Ring& ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % n], c = ring[(i + 2) % n];
    if (orient(a, b, c) == 0.0 && dot(a - b, c - b) > 0.0) return true;
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segmentsIntersect(a, b, ring[j], ring[(j + 1) % n])) return true;
    }
  }
  return false;
}

TEST(FindSelfIntersection, AgreesWithEveryPairOnRandomAndGridRings) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> coordinate(0, 6);  // a small grid: touching, collinear
  std::uniform_int_distribution<int> size(3, 12);
  int simple = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Ring ring(static_cast<std::size_t>(size(rng)));
    for (Vec2& v : ring)
      v = {static_cast<double>(coordinate(rng)), static_cast<double>(coordinate(rng))};
    const EdgePair found = findSelfIntersection(ring);
    ASSERT_EQ(found.found(), selfIntersectsByEveryPair(ring)) << "trial " << trial;
    if (found.found()) {
      EXPECT_LT(found.first, found.second);
      const std::size_t n = ring.size(), i = found.first, j = found.second;
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      EXPECT_TRUE(adjacent ||
                  segmentsIntersect(ring[i], ring[(i + 1) % n], ring[j], ring[(j + 1) % n]))
          << "the pair named must touch";
    }
    simple += !found.found();
  }
  EXPECT_GT(simple, 100) << "some of the rings are simple";
}

TEST(PlaceRing, RotatesAboutOriginThenTranslates) {
  Ring out;
  placeRing(kUnitSquare, std::numbers::pi / 2, {10, 0}, out);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_NEAR(out[1].x, 10.0, 1e-15);  // (1, 0) -> (0, 1) -> (10, 1)
  EXPECT_NEAR(out[1].y, 1.0, 1e-15);
  EXPECT_GT(signedArea(out), 0.0);  // rotation keeps orientation
}

TEST(PlaceRing, AnObjectThatDoesNotTurnIsPlacedAsTheRotationFormulaPlacesIt) {
  // Unturned (±0) it skips the library's cos and sin: the same bits as the formula with them,
  // the signs of zeros included.
  const Ring shape{{0.0, 0.0}, {-0.0, 1.5}, {2.0, -0.0}, {-3.25, -1e-300}, {1e300, 7.0}};
  for (const double angle : {0.0, -0.0}) {
    for (const Vec2 offset : {Vec2{0.0, 0.0}, Vec2{-0.0, -0.0}, Vec2{4.5, -2.0}}) {
      Ring out;
      placeRing(shape, angle, offset, out);
      ASSERT_EQ(out.size(), shape.size());
      const double c = std::cos(angle), s = std::sin(angle);
      for (std::size_t i = 0; i < shape.size(); ++i) {
        const Vec2 v = shape[i];
        const Vec2 expected{c * v.x - s * v.y + offset.x, s * v.x + c * v.y + offset.y};
        EXPECT_TRUE(sameBits(out[i], expected)) << "vertex " << i << ", angle " << angle;
      }
    }
  }
}

TEST(BoundingBox, SpansAllVertices) {
  const Box box = boundingBox(Ring{{-1, 2}, {3, -4}, {0, 5}});
  EXPECT_EQ(box.min, (Vec2{-1, -4}));
  EXPECT_EQ(box.max, (Vec2{3, 5}));
}

TEST(BoundingBox, ItsSquaredDistanceIsThePolygonsOfItsRing) {
  // Inside, on a side, on a corner, beside a side and beyond a corner, and a degenerate box.
  const Box box{{-1, -4}, {3, 5}}, flat{{2, 1}, {2, 1}};
  for (const Vec2 p : {Vec2{0, 0}, Vec2{3, 0}, Vec2{-1, -4}, Vec2{7, 1}, Vec2{1, -9}, Vec2{-4, 9},
                       Vec2{6, -8}, Vec2{-1e6, 3e5}}) {
    SCOPED_TRACE(::testing::Message() << p.x << ", " << p.y);
    const double d = distanceToPolygon(ringOf(box), p);
    EXPECT_NEAR(squaredDistance(box, p), d * d, 1e-12 * (1.0 + d * d));
    EXPECT_DOUBLE_EQ(squaredDistance(flat, p), (p.x - 2) * (p.x - 2) + (p.y - 1) * (p.y - 1));
  }
}

}  // namespace
}  // namespace camcov::geometry

namespace camcov::geometry {
namespace {

TEST(ConvexHull, IsCounterClockwiseWithoutInnerRepeatedOrCollinearPoints) {
  // A square's corners, its centre, an edge's midpoint and a repeated corner.
  const Ring hull = convexHull({{2, 2}, {0, 0}, {1, 1}, {2, 0}, {1, 0}, {0, 2}, {2, 2}});
  EXPECT_EQ(hull, (Ring{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
  EXPECT_GT(signedArea(hull), 0.0);
}

TEST(ConvexHull, OfFewerThanThreeDistinctPointsIsThosePointsSorted) {
  EXPECT_EQ(convexHull({{3, 1}, {3, 1}, {1, 5}}), (Ring{{1, 5}, {3, 1}}));
  EXPECT_EQ(convexHull({{3, 1}}), (Ring{{3, 1}}));
  EXPECT_TRUE(convexHull({}).empty());
}

TEST(ConvexHull, OfCollinearPointsIsTheirTwoEnds) {
  EXPECT_EQ(convexHull({{0, 0}, {1, 1}, {3, 3}, {2, 2}}), (Ring{{0, 0}, {3, 3}}));
}

}  // namespace
}  // namespace camcov::geometry
