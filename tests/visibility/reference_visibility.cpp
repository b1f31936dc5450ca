#include "reference_visibility.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace camcov::visibility::reference {

using geometry::Vec2;

namespace {

constexpr double kPi = std::numbers::pi;

struct RefRing {
  std::vector<Vec2> v;
  bool boundary = false;
  bool solidOnLeft = false;
};

double twiceArea(const std::vector<Vec2>& v) {
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2 a = v[i], b = v[(i + 1) % v.size()];
    sum += a.x * b.y - a.y * b.x;
  }
  return sum;
}

std::vector<RefRing> ringsOf(const kinematics::World& world) {
  std::vector<RefRing> rings;
  auto add = [&rings](const std::vector<Vec2>& in, bool boundary) {
    RefRing ring;
    ring.boundary = boundary;
    for (std::size_t i = 0; i < in.size(); ++i) {
      if (!(in[i] == in[(i + 1) % in.size()])) ring.v.push_back(in[i]);
    }
    const double area = twiceArea(ring.v);
    ring.solidOnLeft = boundary ? area < 0.0 : area > 0.0;
    rings.push_back(ring);
  };
  add(world.boundary, true);
  for (const auto& r : world.obstacles)
    add(r, false);
  for (const auto& r : world.targets)
    add(r, false);
  return rings;
}

double magnitude(Vec2 a) {
  return std::sqrt(a.x * a.x + a.y * a.y);
}

double segmentDistance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  double u = dot(p - a, ab) / dot(ab, ab);
  u = u < 0.0 ? 0.0 : (u > 1.0 ? 1.0 : u);
  return magnitude(p - (a + ab * u));
}

bool insideByWinding(const std::vector<Vec2>& v, Vec2 p) {
  double total = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2 a = v[i] - p, b = v[(i + 1) % v.size()] - p;
    total += std::atan2(cross(a, b), dot(a, b));
  }
  return std::abs(total) > kPi;
}

// Directions blocked right at the viewpoint: counter-clockwise from `from` to `to`.
struct Arc {
  Vec2 from, to;
};

// False if p sees nothing; otherwise fills the arcs blocked by rings p stands on.
bool viewpointStatus(const std::vector<RefRing>& rings, Vec2 p, double eps,
                     std::vector<Arc>& blocked) {
  for (const RefRing& ring : rings) {
    const std::size_t n = ring.v.size();
    bool touching = false;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = ring.v[i], b = ring.v[(i + 1) % n];
      if (magnitude(a - p) <= eps) {
        touching = true;
        const Vec2 before = ring.v[(i + n - 1) % n] - p, after = b - p;
        blocked.push_back(ring.solidOnLeft ? Arc{after, before} : Arc{before, after});
      } else if (magnitude(b - p) > eps && segmentDistance(p, a, b) <= eps) {
        touching = true;
        blocked.push_back(ring.solidOnLeft ? Arc{b - p, a - p} : Arc{a - p, b - p});
      }
    }
    if (!touching && ring.boundary != insideByWinding(ring.v, p)) return false;
  }
  return true;
}

// {t ∈ [0, 1] : f0 + t·f1 > 0}; empty when lo ≥ hi.
Interval positive(double f0, double f1) {
  if (f1 == 0.0) return f0 > 0.0 ? Interval{0.0, 1.0} : Interval{0.0, 0.0};
  const double root = -f0 / f1;
  return f1 > 0.0 ? Interval{std::max(root, 0.0), 1.0} : Interval{0.0, std::min(root, 1.0)};
}

Interval meet(Interval a, Interval b) {
  return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

// The edge as seen from p: direction w(t) = w0 + t·w1.
struct Ray {
  Vec2 w0, w1;
};

// Parameters whose direction lies strictly inside the convex cone from u to v (< π).
Interval cone(const Ray& r, Vec2 u, Vec2 v) {
  return meet(positive(cross(u, r.w0), cross(u, r.w1)), positive(cross(r.w0, v), cross(r.w1, v)));
}

IntervalSet subtract(const IntervalSet& set, Interval cut) {
  if (!(cut.hi > cut.lo)) return set;
  IntervalSet out;
  for (const Interval& i : set) {
    if (cut.hi <= i.lo || cut.lo >= i.hi) {
      out.push_back(i);
      continue;
    }
    if (cut.lo > i.lo) out.push_back({i.lo, cut.lo});
    if (cut.hi < i.hi) out.push_back({cut.hi, i.hi});
  }
  return out;
}

// Removes the parameters whose direction lies in the arc from u counter-clockwise to v.
IntervalSet subtractArc(const IntervalSet& set, const Ray& r, Vec2 u, Vec2 v) {
  const double c = cross(u, v);
  if (c > 0.0) return subtract(set, cone(r, u, v));
  if (c < 0.0) {  // reflex: keep only the opposite convex cone
    const Interval keep = cone(r, v, u);
    return subtract(subtract(set, {0.0, keep.lo}), {std::max(keep.hi, keep.lo), 1.0});
  }
  if (dot(u, v) < 0.0) return subtract(set, positive(cross(u, r.w0), cross(u, r.w1)));
  return set;
}

bool arcContains(const Arc& arc, Vec2 m) {
  const double c = cross(arc.from, arc.to);
  if (c > 0.0) return cross(arc.from, m) > 0.0 && cross(m, arc.to) > 0.0;
  if (c < 0.0) return !(cross(arc.to, m) > 0.0 && cross(m, arc.from) > 0.0);
  return dot(arc.from, arc.to) < 0.0 && cross(arc.from, m) > 0.0;
}

Vec2 unit(double angle) {
  return {std::cos(angle), std::sin(angle)};
}

}  // namespace

double tolerance(const kinematics::World& world) {
  double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
  auto grow = [&](const std::vector<Vec2>& ring) {
    for (const Vec2 v : ring) {
      minX = std::min(minX, v.x);
      minY = std::min(minY, v.y);
      maxX = std::max(maxX, v.x);
      maxY = std::max(maxY, v.y);
    }
  };
  grow(world.boundary);
  for (const auto& r : world.obstacles)
    grow(r);
  for (const auto& r : world.targets)
    grow(r);
  return 1e-12 * std::max(maxX - minX, maxY - minY);
}

std::vector<std::vector<IntervalSet>> visibleIntervals(const kinematics::World& world, Vec2 p,
                                                       double yaw, double halfFov) {
  const std::vector<RefRing> rings = ringsOf(world);
  const double eps = tolerance(world);
  std::vector<std::vector<IntervalSet>> result(world.targets.size());
  for (std::size_t i = 0; i < world.targets.size(); ++i)
    result[i].resize(world.targets[i].size());
  std::vector<Arc> blocked;
  if (!viewpointStatus(rings, p, eps, blocked)) return result;

  for (std::size_t i = 0; i < world.targets.size(); ++i) {
    const auto& target = world.targets[i];
    for (std::size_t k = 0; k < target.size(); ++k) {
      const Vec2 a = target[k], b = target[(k + 1) % target.size()];
      const double len = magnitude(b - a);
      if (len == 0.0) continue;
      if (std::abs(cross(b - a, p - a)) / len <= eps) continue;  // seen edge-on
      const Ray ray{a - p, b - a};
      IntervalSet set{{0.0, 1.0}};
      if (halfFov < kPi) {  // keep the closed wedge: remove the open arc from left to right
        set = subtractArc(set, ray, unit(yaw + halfFov), unit(yaw - halfFov));
      }
      for (const Arc& arc : blocked)
        set = subtractArc(set, ray, arc.from, arc.to);
      for (const RefRing& ring : rings) {
        for (std::size_t j = 0; j < ring.v.size(); ++j) {
          const Vec2 c = ring.v[j], d = ring.v[(j + 1) % ring.v.size()];
          if (c == a && d == b) continue;  // the edge itself
          const double lenF = magnitude(d - c);
          if (segmentDistance(p, c, d) <= eps) continue;  // p stands on it: an arc
          const double side = cross(d - c, p - c);
          if (std::abs(side) <= eps * lenF) continue;  // edge-on: casts no shadow
          const Vec2 u = side > 0.0 ? c - p : d - p, v = side > 0.0 ? d - p : c - p;
          const double s = side > 0.0 ? -1.0 : 1.0;  // beyond F: the sign opposite to p's
          const Interval beyond = positive(s * cross(d - c, a - c), s * cross(d - c, b - a));
          set = subtract(set, meet(cone(ray, u, v), beyond));
        }
      }
      result[i][k] = set;
    }
  }
  return result;
}

double visibleArea(const kinematics::World& world, Vec2 p) {
  const std::vector<RefRing> rings = ringsOf(world);
  const double eps = tolerance(world);
  std::vector<Arc> blocked;
  if (!viewpointStatus(rings, p, eps, blocked)) return 0.0;

  std::vector<double> angles;
  for (const RefRing& ring : rings) {
    for (const Vec2 v : ring.v) {
      if (magnitude(v - p) > eps) angles.push_back(std::atan2(v.y - p.y, v.x - p.x));
    }
  }
  for (const Arc& arc : blocked) {
    angles.push_back(std::atan2(arc.from.y, arc.from.x));
    angles.push_back(std::atan2(arc.to.y, arc.to.x));
  }
  // Where objects overlap, the nearest edge also changes where two edges cross.
  std::vector<std::pair<Vec2, Vec2>> edges;
  for (const RefRing& ring : rings) {
    for (std::size_t j = 0; j < ring.v.size(); ++j)
      edges.push_back({ring.v[j], ring.v[(j + 1) % ring.v.size()]});
  }
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto [a, b] = edges[i];
      const auto [c, d] = edges[j];
      const double den = cross(b - a, d - c);
      if (den == 0.0) continue;
      const double t = cross(c - a, d - c) / den, u = cross(c - a, b - a) / den;
      if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) continue;
      const Vec2 x = a + (b - a) * t;
      if (magnitude(x - p) > eps) angles.push_back(std::atan2(x.y - p.y, x.x - p.x));
    }
  }
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());
  angles.push_back(angles.front() + 2.0 * kPi);

  double area = 0.0;
  for (std::size_t i = 0; i + 1 < angles.size(); ++i) {
    const double a0 = angles[i], a1 = angles[i + 1];
    const Vec2 m = unit(0.5 * (a0 + a1));
    if (std::any_of(blocked.begin(), blocked.end(),
                    [m](const Arc& arc) { return arcContains(arc, m); })) {
      continue;
    }
    double best = INFINITY;
    Vec2 bestC, bestD;
    for (const RefRing& ring : rings) {
      for (std::size_t j = 0; j < ring.v.size(); ++j) {
        const Vec2 c = ring.v[j], d = ring.v[(j + 1) % ring.v.size()];
        if (segmentDistance(p, c, d) <= eps) continue;
        // Seen edge-on: it subtends no angle (and its line would meet no ray).
        if (std::abs(cross(d - c, p - c)) <= eps * magnitude(d - c)) continue;
        const double den = cross(m, d - c);
        if (den == 0.0) continue;
        const double s = cross(c - p, d - c) / den, r = cross(c - p, m) / den;
        if (s > 0.0 && r >= 0.0 && r <= 1.0 && s < best) {
          best = s;
          bestC = c;
          bestD = d;
        }
      }
    }
    if (best == INFINITY) continue;
    const Vec2 u0 = unit(a0), u1 = unit(a1), f = bestD - bestC;
    const double s0 = cross(bestC - p, f) / cross(u0, f), s1 = cross(bestC - p, f) / cross(u1, f);
    area += 0.5 * s0 * s1 * std::sin(a1 - a0);
  }
  return area;
}

bool clearLine(const kinematics::World& world, Vec2 p, Vec2 q, double tol) {
  const std::vector<RefRing> rings = ringsOf(world);
  const double pq = magnitude(q - p);
  if (pq == 0.0) return true;
  for (const RefRing& ring : rings) {
    for (std::size_t j = 0; j < ring.v.size(); ++j) {
      const Vec2 c = ring.v[j], d = ring.v[(j + 1) % ring.v.size()];
      const double cd = magnitude(d - c);
      if (cd == 0.0) continue;
      const double d1 = cross(d - c, p - c) / cd, d2 = cross(d - c, q - c) / cd;
      const double e1 = cross(q - p, c - p) / pq, e2 = cross(q - p, d - p) / pq;
      if (d1 * d2 < 0.0 && std::min(std::abs(d1), std::abs(d2)) > tol && e1 * e2 < 0.0 &&
          std::min(std::abs(e1), std::abs(e2)) > tol) {
        return false;
      }
    }
  }
  const Vec2 mid = (p + q) * 0.5;
  for (const RefRing& ring : rings) {
    double nearest = INFINITY;
    for (std::size_t j = 0; j < ring.v.size(); ++j) {
      nearest = std::min(nearest, segmentDistance(mid, ring.v[j], ring.v[(j + 1) % ring.v.size()]));
    }
    if (nearest > tol && ring.boundary != insideByWinding(ring.v, mid)) return false;
  }
  return true;
}

}  // namespace camcov::visibility::reference
