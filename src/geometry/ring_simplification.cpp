#include "geometry/ring_simplification.h"

#include <algorithm>
#include <utility>

namespace camcov::geometry {

namespace {

// The vertex of `ring` farthest from vertex `from`.
std::size_t farthestFrom(std::span<const Vec2> ring, std::size_t from) {
  std::size_t far = from;
  double best = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double d = norm2(ring[i] - ring[from]);
    if (d > best) {
      best = d;
      far = i;
    }
  }
  return far;
}

}  // namespace

void simplificationOf(std::span<const Vec2> ring, double tolerance,
                      std::span<const std::uint8_t> mustKeep, std::vector<std::uint8_t>& keep) {
  const std::size_t n = ring.size();
  keep.assign(n, 0);
  std::vector<std::size_t> anchors;
  for (std::size_t i = 0; i < mustKeep.size(); ++i) {
    if (mustKeep[i] != 0) anchors.push_back(i);
  }
  // One anchor, or none, leaves the ring whole: a second one, as far as can be, splits it.
  if (anchors.size() < 2) {
    const std::size_t from = anchors.empty() ? 0 : anchors.front();
    const std::size_t far = farthestFrom(ring, from);
    if (far == from) {  // every vertex on one point: nothing to simplify
      keep.assign(n, 1);
      return;
    }
    anchors = {std::min(from, far), std::max(from, far)};
  }
  const double tolerance2 = tolerance * tolerance;
  // Each run between consecutive anchors, by indices that go on past n − 1 (taken modulo n).
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t k = 0; k < anchors.size(); ++k) {
    const std::size_t from = anchors[k];
    const std::size_t to = k + 1 < anchors.size() ? anchors[k + 1] : anchors.front() + n;
    keep[from] = 1;
    runs.emplace_back(from, to);
    while (!runs.empty()) {
      const auto [i, j] = runs.back();
      runs.pop_back();
      const Vec2 a = ring[i % n], b = ring[j % n];
      std::size_t worst = i;
      double worstDistance2 = tolerance2;
      for (std::size_t m = i + 1; m < j; ++m) {
        const double d2 = squaredDistanceToSegment(ring[m % n], a, b);
        if (d2 > worstDistance2) {
          worstDistance2 = d2;
          worst = m;
        }
      }
      if (worst == i) continue;  // every vertex between within tolerance: the edge a–b will do
      keep[worst % n] = 1;
      runs.emplace_back(i, worst);
      runs.emplace_back(worst, j);
    }
  }
  if (std::count(keep.begin(), keep.end(), 1) < 3) keep.assign(n, 1);
}

bool simplificationHolds(std::span<const Vec2> ring, double tolerance,
                         std::span<const std::uint8_t> mustKeep,
                         std::span<const std::uint8_t> keep) {
  const std::size_t n = ring.size();
  if (keep.size() != n) return false;
  std::size_t first = n, kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (keep[i] != 0) {
      first = std::min(first, i);
      ++kept;
    } else if (i < mustKeep.size() && mustKeep[i] != 0) {
      return false;
    }
  }
  if (kept < 3) return false;
  const double tolerance2 = tolerance * tolerance;
  // Each run of dropped vertices against the edge between the kept vertices around it.
  for (std::size_t from = first, k = 0; k < kept; ++k) {
    std::size_t to = from + 1;
    while (keep[to % n] == 0)
      ++to;
    for (std::size_t m = from + 1; m < to; ++m) {
      if (squaredDistanceToSegment(ring[m % n], ring[from % n], ring[to % n]) > tolerance2)
        return false;
    }
    from = to;
  }
  return true;
}

bool simplifiedRing(std::span<const Vec2> ring, double tolerance,
                    std::span<const std::uint8_t> mustKeep, std::vector<std::uint8_t>& keep,
                    Ring& out) {
  if (!simplificationHolds(ring, tolerance, mustKeep, keep))
    simplificationOf(ring, tolerance, mustKeep, keep);
  const auto kept = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 1));
  // A ring that keeps most of its vertices is drawn about as coarsely as its shape: dropping the
  // few (a vertex on a side, a repeated one) saves nothing and only moves results by rounding.
  if (2 * kept > ring.size()) return false;
  Ring simple;
  simple.reserve(kept);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (keep[i] != 0) simple.push_back(ring[i]);
  }
  // A part thinner than the tolerance may have folded, or a sliver of a ring collapsed.
  const double before = signedArea(ring), after = signedArea(simple);
  if (!(before > 0.0 ? after > 0.0 : after < 0.0) || findSelfIntersection(simple).found()) {
    return false;
  }
  out = std::move(simple);
  return true;
}

}  // namespace camcov::geometry
