#pragma once
// Rings drawn by formula, for the tests of any stage (geometry and up).
#include <numbers>

#include "geometry/ring.h"

namespace camcov::testing {

// A regular polygon of `vertices` vertices on the circle about `centre`, counter-clockwise
// from the direction +x: a disc drawn as finely as `vertices` says.
inline geometry::Ring disc(geometry::Vec2 centre, double radius, int vertices) {
  geometry::Ring ring;
  for (int k = 0; k < vertices; ++k)
    ring.push_back(centre + geometry::unitVector(2.0 * std::numbers::pi * k / vertices) * radius);
  return ring;
}

}  // namespace camcov::testing
