#pragma once
// One element s_l of the tessellation S of the targets' boundaries, with visibleBy(s_l)
// (paper section II, equation (1)).
#include <cstdint>

#include "geometry/vec2.h"
#include "scene/camera_set.h"

namespace camcov::visibility {

struct Segment {
  geometry::Vec2 a;            // s_l^(1), first in the target ring's direction
  geometry::Vec2 b;            // s_l^(2)
  std::uint32_t target = 0;    // index into World::targets
  std::uint32_t edge = 0;      // the edge of that ring from vertex `edge` to the next one
  scene::CameraSet visibleBy;  // the cameras that see all of the segment
};

// One camera sees the global target edge `edge` (Occluders::targetEdgeOffset) for parameters
// t in [lo, hi], 0 <= lo < hi <= 1 (0 at the edge's first vertex): what one camera's sweep
// finds, before the cameras' intervals are cut into S.
struct SeenInterval {
  std::uint32_t edge;
  double lo, hi;
};

// The point at parameter t of the edge from a to b, as S places its segments' ends: the
// vertices themselves at t = 0 and 1, so that neighbouring edges share them exactly.
inline geometry::Vec2 pointAt(geometry::Vec2 a, geometry::Vec2 b, double t) {
  return t == 0.0 ? a : t == 1.0 ? b : geometry::lerp(a, b, t);
}

inline double length(const Segment& s) {
  return geometry::distance(s.a, s.b);
}

}  // namespace camcov::visibility
