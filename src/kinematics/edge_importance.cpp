#include "kinematics/edge_importance.h"

#include <algorithm>
#include <cmath>

namespace camcov::kinematics {

bool inFront(const geometry::Ring& placed, std::size_t i, geometry::Vec2 motion, double halfAngle) {
  const geometry::Vec2 a = placed[i], b = placed[(i + 1) % placed.size()];
  const geometry::Vec2 outward{b.y - a.y, a.x - b.x};  // right of a→b: outside a CCW ring
  const double lengths = geometry::norm(outward) * geometry::norm(motion);
  if (lengths == 0.0) return false;
  return geometry::dot(outward, motion) >= lengths * std::cos(halfAngle);
}

void edgeWeightsAt(const scene::MovingObject& object, const geometry::Ring& placed,
                   const std::optional<geometry::Vec2>& motion, std::vector<double>& out) {
  out.resize(placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    double w = object.edgeWeights.empty() ? 1.0 : object.edgeWeights[i];
    if (object.front && motion && inFront(placed, i, *motion, object.front->halfAngle))
      w *= object.front->weight;
    out[i] = w;
  }
}

void normalizeWeights(std::vector<std::vector<double>>& weights) {
  double largest = 0.0;
  for (const std::vector<double>& target : weights) {
    for (const double w : target)
      largest = std::max(largest, w);
  }
  if (!(largest > 0.0)) return;
  for (std::vector<double>& target : weights) {
    for (double& w : target)
      w /= largest;
  }
}

}  // namespace camcov::kinematics
