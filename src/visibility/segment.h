#pragma once
// One element s_l of the tessellation S of the targets' boundaries, with visibleBy(s_l)
// (paper section II, equation (1)).
#include <cstdint>

#include "geometry/vec2.h"

namespace camcov::visibility {

struct Segment {
  geometry::Vec2 a;             // s_l^(1), first in the target ring's direction
  geometry::Vec2 b;             // s_l^(2)
  std::uint32_t target = 0;     // index into World::targets
  std::uint32_t edge = 0;       // the edge of that ring from vertex `edge` to the next one
  std::uint64_t visibleBy = 0;  // bit j set: camera j sees all of the segment
};

inline double length(const Segment& s) {
  return geometry::distance(s.a, s.b);
}

}  // namespace camcov::visibility
