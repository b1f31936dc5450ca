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
                   const std::optional<geometry::Vec2>& motion, double scale,
                   std::vector<double>& out) {
  out.resize(placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    double w = object.edgeWeights.empty() ? 1.0 : object.edgeWeights[i];
    if (object.front && motion && inFront(placed, i, *motion, object.front->halfAngle))
      w *= object.front->weight;
    out[i] = w / scale;
  }
}

double importanceScale(const scene::Scene& scene) {
  double scale = 1.0;
  for (const scene::MovingObject& target : scene.targets) {
    double largest = 1.0;
    if (!target.edgeWeights.empty())
      largest = *std::max_element(target.edgeWeights.begin(), target.edgeWeights.end());
    if (target.front) largest *= std::max(target.front->weight, 1.0);
    scale = std::max(scale, largest);
  }
  return scale;
}

}  // namespace camcov::kinematics
