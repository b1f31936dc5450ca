#pragma once
// Directions around a viewpoint as 32-bit keys: the pseudo-angle (geometry/predicates.h) in
// units of 2^-30, so that a full turn is 2^32 and arithmetic on keys goes round modulo 2^32.
// Internal to the visibility stage: the event sort (PolarEdges) and the occlusion culling
// (OcclusionCulling) share them.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>

#include "geometry/predicates.h"
#include "geometry/ring.h"
#include "geometry/vec2.h"

namespace camcov::visibility {

// The pseudo-angle of d as a 32-bit fixed-point number (16-byte events, and the radix sort's
// digits for free). A quantum, 2^-30, dwarfs the
// pseudo-angle's rounding error (~1e-15), so keys two quanta apart order their directions
// correctly; closer ones need geometry::compareAngle().
inline std::uint32_t quantizedAngle(geometry::Vec2 d) {
  // A vertex at the viewpoint has no direction; callers never use its key, but it must not be
  // 0/0 converted to an integer.
  if (d == geometry::Vec2{}) return 0;
  return static_cast<std::uint32_t>(std::min(geometry::pseudoAngle(d) * 0x1p30, 4294967295.0));
}

// Half a turn in keys: a pseudo-angle turns by 2 over π.
inline constexpr std::uint32_t kHalfTurn = 0x80000000u;

// The keys counter-clockwise from `start` over `width` quanta (modulo 2^32).
struct KeyArc {
  std::uint32_t start = 0;
  std::uint32_t width = 0;
  std::uint32_t end() const { return start + width; }
};

// The arc holding every direction from p to `points` when they lie within less than π of
// each other (a box or a ring seen from outside its box): in offsets from the first point's
// key taken as signed, they all lie within (−π, π), so the least and the greatest bound the
// arc. Empty when the arc comes within a few quanta of π, where rounding could not tell the
// two ways round apart.
inline std::optional<KeyArc> pointsArc(std::span<const geometry::Vec2> points, geometry::Vec2 p) {
  const std::uint32_t reference = quantizedAngle(points[0] - p);
  std::int64_t lo = 0, hi = 0;
  for (const geometry::Vec2 point : points.subspan(1)) {
    const auto offset = static_cast<std::int32_t>(quantizedAngle(point - p) - reference);
    lo = std::min<std::int64_t>(lo, offset);
    hi = std::max<std::int64_t>(hi, offset);
  }
  if (hi - lo >= kHalfTurn - 8) return std::nullopt;
  return KeyArc{reference + static_cast<std::uint32_t>(lo), static_cast<std::uint32_t>(hi - lo)};
}

// The arc a box spans seen from p outside it: between its extreme corners, less than π.
inline std::optional<KeyArc> boxArc(const geometry::Box& box, geometry::Vec2 p) {
  const geometry::Vec2 corners[4] = {
      box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
  return pointsArc(corners, p);
}

}  // namespace camcov::visibility
