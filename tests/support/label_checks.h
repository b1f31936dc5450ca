#pragma once
// Whether a label's box touches something drawn, for the tests of the scene pictures and the
// frames: the tests' own geometry (segment crossings and point location from the geometry
// stage), not the label placer's, so that a bug in the placer cannot hide in its own check.
#include <algorithm>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"

namespace camcov::testing {

inline bool boxesTouch(const geometry::Box& a, const geometry::Box& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

inline bool boxHolds(const geometry::Box& b, geometry::Vec2 p) {
  return b.min.x <= p.x && p.x <= b.max.x && b.min.y <= p.y && p.y <= b.max.y;
}

// The segment crosses a side of the box or lies in it.
inline bool boxMeetsSegment(const geometry::Box& b, geometry::Vec2 p, geometry::Vec2 q) {
  const auto c = geometry::ringOf(b);
  for (std::size_t i = 0; i < 4; ++i) {
    if (geometry::segmentsIntersect(p, q, c[i], c[(i + 1) % 4])) return true;
  }
  return boxHolds(b, p);
}

inline bool boxMeetsLine(const geometry::Box& b, const std::vector<geometry::Vec2>& line,
                         bool closed) {
  if (line.size() == 1) return boxHolds(b, line.front());
  const std::size_t n = line.size(), edges = closed ? n : n - 1;
  for (std::size_t i = 0; i < edges; ++i) {
    if (boxMeetsSegment(b, line[i], line[(i + 1) % n])) return true;
  }
  return false;
}

// A filled polygon: its edges, a corner of the box inside it, or a vertex of it in the box.
inline bool boxMeetsArea(const geometry::Box& b, const std::vector<geometry::Vec2>& ring) {
  if (ring.empty()) return false;
  if (boxMeetsLine(b, ring, true)) return true;
  for (const geometry::Vec2 c : geometry::ringOf(b)) {
    if (geometry::locate(ring, c) != geometry::Containment::Outside) return true;
  }
  return boxHolds(b, ring.front());
}

inline bool boxMeetsDisc(const geometry::Box& b, geometry::Vec2 centre, double radius) {
  const geometry::Vec2 nearest{std::clamp(centre.x, b.min.x, b.max.x),
                               std::clamp(centre.y, b.min.y, b.max.y)};
  return geometry::distance(nearest, centre) <= radius;
}

}  // namespace camcov::testing
