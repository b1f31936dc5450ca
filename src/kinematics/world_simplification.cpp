#include "kinematics/world_simplification.h"

#include <algorithm>

#include "geometry/ring_simplification.h"

namespace camcov::kinematics {

namespace {

// `ring` simplified into `out`, or copied; `weights` (empty: none) are its edges' and follow its
// vertices into `outWeights`. `keep`: the vertices kept of this ring the last time.
bool simplify(const geometry::Ring& ring, const std::vector<double>& weights, double tolerance,
              std::vector<std::uint8_t>& keep, SimplificationScratch& s, geometry::Ring& out,
              std::vector<double>& outWeights) {
  s.mustKeep.clear();
  if (!weights.empty()) {
    s.mustKeep.resize(ring.size());
    for (std::size_t v = 0; v < ring.size(); ++v)
      s.mustKeep[v] = weights[v] != weights[v == 0 ? ring.size() - 1 : v - 1];
  }
  if (!geometry::simplifiedRing(ring, tolerance, s.mustKeep, keep, out)) {
    out = ring;
    outWeights = weights;
    return false;
  }
  // The edge from a kept vertex takes that vertex's edge weight: the run it replaces has one.
  outWeights.clear();
  if (!weights.empty()) {
    for (std::size_t v = 0; v < keep.size(); ++v) {
      if (keep[v] != 0) outWeights.push_back(weights[v]);
    }
  }
  return true;
}

}  // namespace

bool hasFinelyDrawnObjects(const World& world) {
  const auto fine = [](const geometry::Ring& r) { return r.size() >= geometry::kFewestSimplified; };
  return std::any_of(world.targets.begin(), world.targets.end(), fine) ||
         std::any_of(world.obstacles.begin(), world.obstacles.end(), fine);
}

bool simplifyObjects(const World& world, double tolerance, World& out,
                     SimplificationScratch& scratch) {
  // Field by field, so that a ring that is simplified is never copied whole.
  out.time = world.time;
  out.boundary = world.boundary;
  out.targetIds = world.targetIds;
  out.obstacleIds = world.obstacleIds;
  out.resolution = world.resolution;
  out.targets.resize(world.targets.size());
  out.obstacles.resize(world.obstacles.size());
  out.targetEdgeWeights.resize(world.targetEdgeWeights.size());
  scratch.targetKeep.resize(world.targets.size());
  scratch.obstacleKeep.resize(world.obstacles.size());
  const std::vector<double> none;
  std::vector<double> noWeights;
  bool any = false;
  for (std::size_t i = 0; i < world.targets.size(); ++i) {
    const bool weighted = i < world.targetEdgeWeights.size();
    any = simplify(world.targets[i], weighted ? world.targetEdgeWeights[i] : none, tolerance,
                   scratch.targetKeep[i], scratch, out.targets[i],
                   weighted ? out.targetEdgeWeights[i] : noWeights) ||
          any;
  }
  for (std::size_t i = 0; i < world.obstacles.size(); ++i) {
    any = simplify(world.obstacles[i], none, tolerance, scratch.obstacleKeep[i], scratch,
                   out.obstacles[i], noWeights) ||
          any;
  }
  return any;
}

}  // namespace camcov::kinematics
