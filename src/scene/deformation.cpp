#include "scene/deformation.h"

#include <cmath>

namespace camcov::scene {

void localShapeAt(const MovingObject& object, double t, geometry::Ring& out) {
  if (!object.deformation) {
    out.assign(object.shape.begin(), object.shape.end());
    return;
  }
  const Deformation& d = *object.deformation;
  double phase = std::fmod(t, d.period);
  if (phase < 0.0) phase += d.period;
  // Find the keyframe interval [t0, t1] holding the phase; the base shape closes the cycle.
  const geometry::Ring* from = &object.shape;
  const geometry::Ring* to = &object.shape;
  double t0 = 0.0, t1 = d.period;
  for (const auto& frame : d.keyframes) {
    if (phase < frame.time) {
      to = &frame.shape;
      t1 = frame.time;
      break;
    }
    from = &frame.shape;
    t0 = frame.time;
  }
  const double u = (phase - t0) / (t1 - t0);
  out.resize(object.shape.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = geometry::lerp((*from)[i], (*to)[i], u);
}

}  // namespace camcov::scene
