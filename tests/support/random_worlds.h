#pragma once
// Seeded random worlds and poses for the reward's property tests: the same on every machine.
#include <numbers>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "support/splitmix64.h"

namespace camcov::testing {

// A 40 m room with quadrilateral and triangular targets and obstacles, some touching (a shared
// edge: pieces seen by two targets), one target with a repeated vertex (an edge of no length).
inline kinematics::World randomWorld(SplitMix64& random) {
  kinematics::World w;
  w.boundary = {{-20, -20}, {20, -20}, {20, 20}, {-20, 20}};
  for (int i = 0; i < 8; ++i) {
    const geometry::Vec2 c{random.uniform(-15, 15), random.uniform(-15, 15)};
    const double r = random.uniform(0.5, 2.5);
    geometry::Ring ring;
    const int n = i % 3 == 0 ? 3 : 4;
    for (int k = 0; k < n; ++k) {
      const double a = (k + random.uniform(0.2, 0.8)) * 2 * std::numbers::pi / n;
      ring.push_back(c + r * geometry::unitVector(a));
    }
    (i % 4 == 3 ? w.obstacles : w.targets).push_back(ring);
  }
  // Two squares sharing a side, and a target with a repeated vertex.
  w.targets.push_back({{1, 16}, {3, 16}, {3, 18}, {1, 18}});
  w.targets.push_back({{3, 16}, {5, 16}, {5, 18}, {3, 18}});
  w.targets.push_back({{-16, 16}, {-14, 16}, {-14, 16}, {-14, 18}});
  return w;
}

inline geometry::Pose randomPose(SplitMix64& random) {
  return {random.uniform(-19, 19), random.uniform(-19, 19),
          random.uniform(-std::numbers::pi, std::numbers::pi)};
}

}  // namespace camcov::testing
