#pragma once
// Simple polygons as open vertex rings. Convention used everywhere above this layer:
// counter-clockwise, first vertex not repeated, at least 3 vertices.
#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

#include "geometry/vec2.h"

namespace camcov::geometry {

using Ring = std::vector<Vec2>;

// Positive for counter-clockwise rings (shoelace formula).
double signedArea(std::span<const Vec2> ring);
double perimeter(std::span<const Vec2> ring);
// Drops a repeated closing vertex and reverses clockwise rings: the loader's normalisation.
void normalizeRing(Ring& ring);

enum class Containment { Outside, OnBoundary, Inside };
// Point location with the boundary widened by `tolerance` (an absolute distance).
Containment locate(std::span<const Vec2> ring, Vec2 p, double tolerance = 1e-9);

double distanceToSegment(Vec2 p, Vec2 a, Vec2 b);
double squaredDistanceToSegment(Vec2 p, Vec2 a, Vec2 b);
Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b);
// The point of the ring's boundary closest to p.
Vec2 closestPointOnBoundary(std::span<const Vec2> ring, Vec2 p);
// Distance from p to the ring's boundary (edges only, ignores the interior).
double distanceToBoundary(std::span<const Vec2> ring, Vec2 p);
// Shortest distance between closed segments [a, b] and [c, d] (0 if they touch).
double distanceBetweenSegments(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
// The parameters [t0, t1] ⊆ [0, 1] of the points a + t (b − a) within `radius` of `centre` (a
// disc meets a segment in one piece); false if none, or only a single point. An infinite radius
// gives [0, 1].
bool discOnSegment(Vec2 centre, double radius, Vec2 a, Vec2 b, double& t0, double& t1);
// Shortest distance from segment [a, b] to the ring's boundary (0 if it touches or crosses).
double distanceSegmentToBoundary(std::span<const Vec2> ring, Vec2 a, Vec2 b);
// Distance from p to the closed polygon: 0 inside, else the distance to the boundary.
double distanceToPolygon(std::span<const Vec2> ring, Vec2 p);
// Shortest distance between the closed polygons a and b (0 if they overlap).
double distanceBetweenPolygons(std::span<const Vec2> a, std::span<const Vec2> b);

// Do closed segments [a, b] and [c, d] share a point?
bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
// Index pair (i, j), i < j, of two non-adjacent edges that touch (or adjacent ones that fold
// back over each other), or {npos, npos} if the ring is simple. Edge i runs from ring[i] to
// ring[i+1]. The exact pairwise test on the pairs whose boxes overlap, found by sweeping the
// edges in x: near-linear for rings whose edges are short against the ring (a 100,000-vertex
// room in milliseconds), quadratic only when most edges overlap in x and y.
struct EdgePair {
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  std::size_t first = npos;
  std::size_t second = npos;
  bool found() const { return first != npos; }
};
EdgePair findSelfIntersection(std::span<const Vec2> ring);

// Rotate every vertex by `angle` about the origin, then translate by `offset`, in place.
void transformRing(Ring& ring, double angle, Vec2 offset);
// The same from a local shape into `out` (its buffer reused).
void placeRing(std::span<const Vec2> local, double angle, Vec2 offset, Ring& out);

// The convex hull of `points`, counter-clockwise (Andrew's monotone chain), repeated and
// collinear points dropped; fewer than three distinct points come back as they are, sorted.
Ring convexHull(std::vector<Vec2> points);

struct Box {
  Vec2 min;
  Vec2 max;
};
Box boundingBox(std::span<const Vec2> ring);
// Closed boxes: sharing a side or a corner counts as overlapping, a point on a side as inside.
inline bool overlaps(const Box& a, const Box& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}
// The box grown by `margin` on every side.
inline Box grown(const Box& box, double margin) {
  return {{box.min.x - margin, box.min.y - margin}, {box.max.x + margin, box.max.y + margin}};
}
inline bool contains(const Box& box, Vec2 p) {
  return box.min.x <= p.x && p.x <= box.max.x && box.min.y <= p.y && p.y <= box.max.y;
}
inline bool contains(const Box& outer, const Box& inner) {
  return contains(outer, inner.min) && contains(outer, inner.max);
}
// The squared distance from p to the box (0 inside): never more than to anything in the box,
// so a cheap lower bound of an object's distance from its bounding box.
inline double squaredDistance(const Box& box, Vec2 p) {
  const double dx = std::max({box.min.x - p.x, 0.0, p.x - box.max.x});
  const double dy = std::max({box.min.y - p.y, 0.0, p.y - box.max.y});
  return dx * dx + dy * dy;
}
inline double area(const Box& box) {
  return (box.max.x - box.min.x) * (box.max.y - box.min.y);
}
// The box as a counter-clockwise ring, from its lower left corner.
inline Ring ringOf(const Box& box) {
  return {box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
}

}  // namespace camcov::geometry
