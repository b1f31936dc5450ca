#include "scene/deformation.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace camcov::scene {

void localShapeAt(const MovingObject& object, double t, geometry::Ring& out) {
  if (!object.deformation) {
    out.assign(object.shape.begin(), object.shape.end());
    return;
  }
  const Deformation& d = *object.deformation;
  double phase = std::fmod(t, d.period);
  if (phase < 0.0) phase += d.period;
  // The keyframe interval [t0, t1] holding the phase (times increase: a binary search); the
  // base shape opens and closes the cycle.
  const auto next =
      std::upper_bound(d.keyframes.begin(), d.keyframes.end(), phase,
                       [](double p, const DeformationKeyframe& k) { return p < k.time; });
  const geometry::Ring* from =
      next == d.keyframes.begin() ? &object.shape : &std::prev(next)->shape;
  const geometry::Ring* to = next == d.keyframes.end() ? &object.shape : &next->shape;
  const double t0 = next == d.keyframes.begin() ? 0.0 : std::prev(next)->time;
  const double t1 = next == d.keyframes.end() ? d.period : next->time;
  const double u = (phase - t0) / (t1 - t0);
  out.resize(object.shape.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = geometry::lerp((*from)[i], (*to)[i], u);
}

}  // namespace camcov::scene
