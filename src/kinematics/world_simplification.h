#pragma once
// A world with its finely drawn objects redrawn coarser, for a method that judges many
// poses in it (our method's rewards: docs/method.md, "Finely drawn objects"). The boundary,
// the ids and every object too coarse to lose a vertex stay as they are.
#include <cstdint>
#include <vector>

#include "kinematics/world.h"

namespace camcov::kinematics {

// What simplifyObjects() keeps between calls: its buffers, and the vertices it kept of each
// target and obstacle, tried first at the next instant (rigid motion keeps them good).
struct SimplificationScratch {
  std::vector<std::uint8_t> mustKeep;
  std::vector<std::vector<std::uint8_t>> targetKeep, obstacleKeep;
};

// Whether simplifyObjects() could simplify any ring of `world`: one has at least
// geometry::kFewestSimplified vertices. Most worlds draw every object coarsely, and a model
// judging them asks at every instant.
bool hasFinelyDrawnObjects(const World& world);

// `world` with each target and obstacle ring simplified to within `tolerance`, metres
// (geometry/ring_simplification.h), into `out`; true if any ring lost a vertex, else `out` is
// a copy of `world`. A target's edge weights stay: a vertex where the weight changes is kept,
// and an edge that replaces a run of edges takes their common weight.
bool simplifyObjects(const World& world, double tolerance, World& out,
                     SimplificationScratch& scratch);

}  // namespace camcov::kinematics
