#pragma once
// The world at one instant t: every polygon in world coordinates, as the controller sees it.
// This is the paper's X(t) = (T(t), O(t)) plus the time-invariant boundary B (section II).
#include <vector>

#include "geometry/ring.h"

namespace camcov::kinematics {

struct World {
  double time = 0.0;                      // t, seconds
  geometry::Ring boundary;                // B: simple, CCW, occludes
  std::vector<geometry::Ring> targets;    // T(t): CCW rings; their boundaries are covered
  std::vector<geometry::Ring> obstacles;  // O(t): CCW rings; occlude, are not covered
};

}  // namespace camcov::kinematics
