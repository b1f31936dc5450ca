#include "geometry/ring.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

double distanceToBoundary(std::span<const Vec2> ring, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    best = std::min(best, squaredDistanceToSegment(p, ring[i], ring[(i + 1) % n]));
  }
  return std::sqrt(best);
}

namespace {

// Crossing number with the half-open rule, so a ray through a vertex counts once. For p off
// the boundary.
bool strictlyInside(std::span<const Vec2> ring, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
    const Vec2 a = ring[i], b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double xCross = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < xCross) inside = !inside;
    }
  }
  return inside;
}

}  // namespace

Containment locate(std::span<const Vec2> ring, Vec2 p, double tolerance) {
  if (distanceToBoundary(ring, p) <= tolerance) return Containment::OnBoundary;
  return strictlyInside(ring, p) ? Containment::Inside : Containment::Outside;
}

double distanceToPolygon(std::span<const Vec2> ring, Vec2 p) {
  const double d = distanceToBoundary(ring, p);
  if (d == 0.0) return 0.0;
  return strictlyInside(ring, p) ? 0.0 : d;
}

bool segmentsIntersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
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
  const double c = std::cos(angle), s = std::sin(angle);
  for (Vec2& v : ring)
    v = {c * v.x - s * v.y + offset.x, s * v.x + c * v.y + offset.y};
}

void placeRing(std::span<const Vec2> local, double angle, Vec2 offset, Ring& out) {
  out.assign(local.begin(), local.end());
  transformRing(out, angle, offset);
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
