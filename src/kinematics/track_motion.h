#pragma once
// Recorded motion (scene::Track): the reference point moves linearly from one sample
// to the next, a gap between two samples included, and the heading turns the short way round
// between them. Before the first sample and after the last the object is absent; asked there,
// it answers with the nearest sample.
#include <utility>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::kinematics {

class TrackMotion {
 public:
  explicit TrackMotion(scene::Track track) : track_(std::move(track)) {}

  geometry::Vec2 positionAt(double t) const;
  double headingAt(double t) const;  // 0 without recorded headings
  // The fastest the reference point moves between two samples, m/s, and the fastest turn,
  // rad/s: bounds for the safety layer's continuous-time accounting.
  double maxSpeed() const;
  double maxTurnRate() const;

 private:
  // The sample interval [k, k + 1] holding t (clamped to the ends) and where t lies in it.
  std::pair<std::size_t, double> locate(double t) const;

  scene::Track track_;
};

}  // namespace camcov::kinematics
