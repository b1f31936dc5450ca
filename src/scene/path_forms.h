#pragma once
// The written forms of a path mapped onto the one the rest of camcov follows: a closed loop of
// waypoints (kinematics/path_motion.h). POLYGON is that loop as written and POINT a loop of one
// point; a LINESTRING, back and forth along a polyline, unfolds here.
#include <span>
#include <vector>

#include "geometry/vec2.h"

namespace camcov::scene {

// The loop that goes out along `polyline` and back: p0, p1, …, pn, p(n−1), …, p1 (then, closing
// the loop, p0 again), at constant speed and turning round at either end. Consecutive repeated
// points are dropped first (a zero-length leg takes no time). Fewer than 2 distinct points give
// the one point left (or nothing): the caller refuses that as a path that never moves.
std::vector<geometry::Vec2> backAndForthLoop(std::span<const geometry::Vec2> polyline);

}  // namespace camcov::scene
