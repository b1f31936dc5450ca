#include "geometry/ring.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

namespace camcov::geometry {

double signedArea(std::span<const Vec2> ring) {
  double twiceArea = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    twiceArea += cross(ring[i], ring[(i + 1) % n]);
  }
  return 0.5 * twiceArea;
}

double perimeter(std::span<const Vec2> ring) {
  double length = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i)
    length += distance(ring[i], ring[(i + 1) % n]);
  return length;
}

void normalizeRing(Ring& ring) {
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  if (signedArea(ring) < 0.0) std::reverse(ring.begin(), ring.end());
}

Vec2 closestPointOnSegment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = norm2(ab);
  const double u = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + ab * u;
}

double distanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
  return distance(p, closestPointOnSegment(p, a, b));
}

double squaredDistanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
  return norm2(p - closestPointOnSegment(p, a, b));
}

bool discOnSegment(Vec2 centre, double radius, Vec2 a, Vec2 b, double& t0, double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  // Both ends inside: all of it (a disc is convex). Also what keeps a radius so large that r²
  // or the products below overflow from reading as no disc at all.
  const double r2 = radius * radius;
  if (dot(a - centre, a - centre) <= r2 && dot(b - centre, b - centre) <= r2) return true;
  // |f + t·d|² = r² with f = a − centre, d = b − a: t²·d·d + 2t·f·d + f·f − r² = 0.
  const Vec2 d = b - a, f = a - centre;
  const double dd = dot(d, d), fd = dot(f, d);
  const double c = dot(f, f) - r2;
  if (dd == 0.0) return c <= 0.0;
  const double discriminant = fd * fd - dd * c;
  if (discriminant < 0.0) return false;
  // The root of larger magnitude first, then the other from their product: no cancellation.
  const double q = -(fd + std::copysign(std::sqrt(discriminant), fd));
  double lo = q / dd, hi = q != 0.0 ? c / q : lo;
  if (lo > hi) std::swap(lo, hi);
  t0 = std::max(lo, 0.0);
  t1 = std::min(hi, 1.0);
  return t0 < t1;
}

double distanceBetweenSegments(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (segmentsIntersect(a, b, c, d)) return 0.0;
  // Disjoint segments are closest at an endpoint of one of them.
  return std::sqrt(
      std::min({squaredDistanceToSegment(a, c, d), squaredDistanceToSegment(b, c, d),
                squaredDistanceToSegment(c, a, b), squaredDistanceToSegment(d, a, b)}));
}

double distanceSegmentToBoundary(std::span<const Vec2> ring, Vec2 a, Vec2 b) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    best = std::min(best, distanceBetweenSegments(a, b, ring[i], ring[(i + 1) % n]));
  }
  return best;
}

Vec2 closestPointOnBoundary(std::span<const Vec2> ring, Vec2 p) {
  Vec2 best = ring.empty() ? p : ring[0];
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Vec2 q = closestPointOnSegment(p, ring[i], ring[(i + 1) % n]);
    if (const double d = distance(p, q); d < bestDistance) {
      bestDistance = d;
      best = q;
    }
  }
  return best;
}

namespace {

// Edge i of a ring runs from ring[i] to ring[(i + 1) % n]. The two loops below take the edges
// [first, last) of a ring, for the whole ring and for EdgeBlocks' blocks alike.

// min(best, squaredDistanceToSegment(p, edge)) over the edges.
double edgesSquaredDistance(std::span<const Vec2> ring, std::size_t first, std::size_t last, Vec2 p,
                            double best) {
  const std::size_t n = ring.size();
  for (std::size_t i = first; i < last; ++i)
    best = std::min(best, squaredDistanceToSegment(p, ring[i], ring[i + 1 == n ? 0 : i + 1]));
  return best;
}

// Whether an odd number of the edges cross the ray from p towards +x, with the half-open rule,
// so that a ray through a vertex counts once: the crossing number's parity, for p off the
// boundary.
bool edgesCrossOddly(std::span<const Vec2> ring, std::size_t first, std::size_t last, Vec2 p) {
  bool odd = false;
  const std::size_t n = ring.size();
  for (std::size_t i = first; i < last; ++i) {
    const Vec2 a = ring[i + 1 == n ? 0 : i + 1], b = ring[i];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double xCross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < xCross) odd = !odd;
    }
  }
  return odd;
}

// A long ring's edges in blocks of consecutive ones, each with the box of its vertices, so that
// a query about one point skips the blocks that cannot matter to it: a target of thousands of
// vertices is mostly far from a camera, and the edges of a round one cross few horizontal
// lines. Block b holds edges [b·k, (b + 1)·k). The answers are those of the loops above over
// every edge, to the bit: a block is skipped only where none of its edges could change them.
class EdgeBlocks {
 public:
  static constexpr std::size_t kEdges = 16;
  // Rings of fewer edges are not blocked: the boxes would cost more than they save.
  static constexpr std::size_t kFewest = 2 * kEdges;

  explicit EdgeBlocks(std::span<const Vec2> ring) : ring_(ring) {
    const std::size_t n = ring.size();
    boxes_.reserve((n + kEdges - 1) / kEdges);
    for (std::size_t start = 0; start < n; start += kEdges) {
      const std::size_t end = std::min(n, start + kEdges);
      Box box = boundingBox(ring.subspan(start, end - start));
      const Vec2 last = ring[end % n];  // the end of the block's last edge
      box.min = {std::min(box.min.x, last.x), std::min(box.min.y, last.y)};
      box.max = {std::max(box.max.x, last.x), std::max(box.max.y, last.y)};
      boxes_.push_back(box);
    }
  }

  // edgesSquaredDistance over every edge: the nearest block first, then the others that could
  // hold a nearer edge.
  double squaredDistance(Vec2 p) const {
    // The computed edge distances and box distances each round by a few ulps of the
    // coordinates; a block is skipped only when its box is farther than the best by far more.
    double scale = std::max(std::abs(p.x), std::abs(p.y));
    std::size_t nearest = 0;
    double nearestGap = std::numeric_limits<double>::infinity();
    for (std::size_t b = 0; b < boxes_.size(); ++b) {
      const Box& box = boxes_[b];
      scale = std::max({scale, std::abs(box.min.x), std::abs(box.min.y), std::abs(box.max.x),
                        std::abs(box.max.y)});
      if (const double gap = boxGap(box, p); gap < nearestGap) {
        nearestGap = gap;
        nearest = b;
      }
    }
    const double slack = 1e-9 * (1.0 + scale);
    double best = blockSquaredDistance(nearest, p, std::numeric_limits<double>::infinity());
    double reach = std::sqrt(best) + slack;
    for (std::size_t b = 0; b < boxes_.size(); ++b) {
      if (b == nearest || boxGap(boxes_[b], p) > reach) continue;
      if (const double d = blockSquaredDistance(b, p, best); d < best) {
        best = d;
        reach = std::sqrt(best) + slack;
      }
    }
    return best;
  }

  // edgesCrossOddly over every edge: a block wholly above p's horizontal line, or wholly on or
  // below it, holds no edge that crosses it.
  bool crossesOddly(Vec2 p) const {
    bool odd = false;
    for (std::size_t b = 0; b < boxes_.size(); ++b) {
      if (boxes_[b].min.y > p.y || boxes_[b].max.y <= p.y) continue;
      if (edgesCrossOddly(ring_, b * kEdges, end(b), p)) odd = !odd;
    }
    return odd;
  }

 private:
  std::size_t end(std::size_t b) const { return std::min(ring_.size(), (b + 1) * kEdges); }
  double blockSquaredDistance(std::size_t b, Vec2 p, double best) const {
    return edgesSquaredDistance(ring_, b * kEdges, end(b), p, best);
  }
  // Distance from p to the box (0 inside), never more than to anything in it.
  static double boxGap(const Box& box, Vec2 p) {
    return std::sqrt(geometry::squaredDistance(box, p));
  }

  std::span<const Vec2> ring_;
  // One allocation a query of a long ring, against its edges' work; nothing shared.
  std::vector<Box> boxes_;
};

// A query's answers: the distance to the boundary, then whether p is inside, from the
// blocks of a long ring or from every edge of a short one.
class BoundaryQuery {
 public:
  BoundaryQuery(std::span<const Vec2> ring, Vec2 p) : ring_(ring), p_(p) {
    if (ring.size() >= EdgeBlocks::kFewest) blocks_.emplace(ring);
  }
  double distance() const {
    return std::sqrt(blocks_ ? blocks_->squaredDistance(p_)
                             : edgesSquaredDistance(ring_, 0, ring_.size(), p_,
                                                    std::numeric_limits<double>::infinity()));
  }
  bool strictlyInside() const {
    return blocks_ ? blocks_->crossesOddly(p_) : edgesCrossOddly(ring_, 0, ring_.size(), p_);
  }

 private:
  std::span<const Vec2> ring_;
  Vec2 p_;
  std::optional<EdgeBlocks> blocks_;
};

}  // namespace

double distanceToBoundary(std::span<const Vec2> ring, Vec2 p) {
  return BoundaryQuery(ring, p).distance();
}

Containment locate(std::span<const Vec2> ring, Vec2 p, double tolerance) {
  const BoundaryQuery query(ring, p);
  if (query.distance() <= tolerance) return Containment::OnBoundary;
  return query.strictlyInside() ? Containment::Inside : Containment::Outside;
}

double distanceToPolygon(std::span<const Vec2> ring, Vec2 p) {
  const BoundaryQuery query(ring, p);
  const double d = query.distance();
  if (d == 0.0) return 0.0;
  return query.strictlyInside() ? 0.0 : d;
}

bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  // [c, d] parallel to an axis with a and b strictly on one side of its line: they do not meet.
  // The test below says so too (one of each orientation's two products is zero, so its signs
  // are exact, and no end lies within the other segment's box); rooms' walls are such, and this
  // answers most of the motion checks against them without a product.
  if (c.y == d.y && ((a.y > c.y && b.y > c.y) || (a.y < c.y && b.y < c.y))) return false;
  if (c.x == d.x && ((a.x > c.x && b.x > c.x) || (a.x < c.x && b.x < c.x))) return false;
  const double d1 = orient(c, d, a), d2 = orient(c, d, b);
  const double d3 = orient(a, b, c), d4 = orient(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  // Touching or collinear cases: an endpoint lying on the other segment.
  auto onSegment = [](Vec2 p, Vec2 q, Vec2 r) {  // r on [p, q], given collinear
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  return (d1 == 0 && onSegment(c, d, a)) || (d2 == 0 && onSegment(c, d, b)) ||
         (d3 == 0 && onSegment(a, b, c)) || (d4 == 0 && onSegment(a, b, d));
}

double distanceBetweenPolygons(std::span<const Vec2> a, std::span<const Vec2> b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  if (locate(a, b[0], 0.0) != Containment::Outside ||
      locate(b, a[0], 0.0) != Containment::Outside) {
    return 0.0;
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Vec2 a0 = a[i], a1 = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Vec2 b0 = b[j], b1 = b[(j + 1) % b.size()];
      if (segmentsIntersect(a0, a1, b0, b1)) return 0.0;
      best = std::min({best, distanceToSegment(a0, b0, b1), distanceToSegment(a1, b0, b1),
                       distanceToSegment(b0, a0, a1), distanceToSegment(b1, a0, a1)});
    }
  }
  return best;
}

EdgePair findSelfIntersection(std::span<const Vec2> ring) {
  const std::size_t n = ring.size();
  const auto edgeEnd = [&](std::size_t i) { return ring[(i + 1) % n]; };
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i], b = edgeEnd(i), c = ring[(i + 2) % n];
    // Adjacent edges share b; they only collide if the second folds back over the first.
    if (orient(a, b, c) == 0.0 && dot(a - b, c - b) > 0.0)
      return {std::min(i, (i + 1) % n), std::max(i, (i + 1) % n)};
  }
  // Sweep and prune: edges by the left end of their box; an edge meets only those that start
  // before it ends in x, and of those only the ones it overlaps in y.
  struct Span {
    double minX, maxX, minY, maxY;
    std::size_t edge;
  };
  std::vector<Span> spans(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = ring[i], b = edgeEnd(i);
    spans[i] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y), i};
  }
  std::sort(spans.begin(), spans.end(), [](const Span& p, const Span& q) {
    return std::tie(p.minX, p.edge) < std::tie(q.minX, q.edge);
  });
  for (std::size_t s = 0; s < n; ++s) {
    const Span& e = spans[s];
    for (std::size_t t = s + 1; t < n && spans[t].minX <= e.maxX; ++t) {
      const Span& f = spans[t];
      if (f.maxY < e.minY || f.minY > e.maxY) continue;
      const std::size_t i = std::min(e.edge, f.edge), j = std::max(e.edge, f.edge);
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // adjacent: checked above
      if (segmentsIntersect(ring[i], edgeEnd(i), ring[j], edgeEnd(j))) return {i, j};
    }
  }
  return {};
}

void transformRing(Ring& ring, double angle, Vec2 offset) {
  placeRing(ring, angle, offset, ring);  // each vertex read before it is written
}

void placeRing(std::span<const Vec2> local, double angle, Vec2 offset, Ring& out) {
  // Most objects do not turn (angle ±0), and the simulator's contact search places them many
  // times a step: cos(±0) = 1 and sin(±0) = ±0 without the library's call.
  const bool turned = angle != 0.0;
  const double c = turned ? std::cos(angle) : 1.0, s = turned ? std::sin(angle) : angle;
  out.resize(local.size());  // the same size when local is out: nothing moves
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Vec2 v = local[i];
    out[i] = {c * v.x - s * v.y + offset.x, s * v.x + c * v.y + offset.y};
  }
}

Box boundingBox(std::span<const Vec2> ring) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box box{{inf, inf}, {-inf, -inf}};
  for (const Vec2 v : ring) {
    box.min = {std::min(box.min.x, v.x), std::min(box.min.y, v.y)};
    box.max = {std::max(box.max.x, v.x), std::max(box.max.y, v.y)};
  }
  return box;
}

Ring convexHull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](Vec2 p, Vec2 q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); });
  points.erase(std::unique(points.begin(), points.end(),
                           [](Vec2 p, Vec2 q) { return p.x == q.x && p.y == q.y; }),
               points.end());
  if (points.size() < 3) return points;
  Ring hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && orient(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
      --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && orient(hull[k - 2], hull[k - 1], points[i]) <= 0.0)
      --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace camcov::geometry
