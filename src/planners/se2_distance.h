#pragma once
// OMPL's SE2StateSpace::distance, worked out from two poses without its virtual calls: the
// roadmap's neighbour grid and eq. (10)'s motion cost measure with it, to the bit what OMPL
// would give (tests/planners/grid_nearest_neighbors_test.cpp checks it against OMPL).
#include <cmath>
#include <numbers>

#include "geometry/vec2.h"

namespace camcov::planners {

// OMPL's compound space sums each component's distance times its weight (1 for R², ½ for
// SO(2)) from 0; R²'s is the root of 0 + Δx² + Δy², SO(2)'s |Δγ| or 2π − |Δγ| past π. The same
// operations in the same order give the same bits (the build does not fuse multiply-adds).
inline double se2Distance(const geometry::Pose& a, const geometry::Pose& b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  double squares = 0.0;
  squares += dx * dx;
  squares += dy * dy;
  const double turn = std::fabs(a.yaw - b.yaw);
  const double so2 = turn > std::numbers::pi ? 2.0 * std::numbers::pi - turn : turn;
  double distance = 0.0;
  distance += 1.0 * std::sqrt(squares);
  distance += 0.5 * so2;
  return distance;
}

}  // namespace camcov::planners
