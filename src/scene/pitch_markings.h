#pragma once
// The markings of a football pitch (Laws of the Game, law 1), as polylines in metres for the
// frames and the explorer to draw: touch and goal lines, halfway line, centre circle (9.15 m)
// and spot, both penalty areas (16.5 m deep, 40.32 m wide) with their spots (11 m) and arcs,
// both goal areas (5.5 m, 18.32 m). Closed shapes repeat their first point.
#include <vector>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::scene {

std::vector<std::vector<geometry::Vec2>> pitchMarkings(const Pitch& pitch);

}  // namespace camcov::scene
