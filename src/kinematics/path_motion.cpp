#include "kinematics/path_motion.h"

#include <algorithm>
#include <cmath>

namespace camcov::kinematics {

PathMotion::PathMotion(std::span<const geometry::Vec2> waypoints, double velocity)
    : waypoints_(waypoints.begin(), waypoints.end()), velocity_(velocity) {
  arcLengthAt_.reserve(waypoints_.size());
  for (std::size_t i = 0; i < waypoints_.size(); ++i) {
    arcLengthAt_.push_back(loopLength_);
    loopLength_ += geometry::distance(waypoints_[i], waypoints_[(i + 1) % waypoints_.size()]);
  }
}

geometry::Vec2 PathMotion::positionAt(double t) const {
  if (loopLength_ == 0.0) return waypoints_.front();
  double s = std::fmod(velocity_ * t, loopLength_);
  if (s < 0.0) s += loopLength_;
  // Last waypoint whose arc length is <= s; the leg from it leads to the next (cyclically).
  const auto it = std::upper_bound(arcLengthAt_.begin(), arcLengthAt_.end(), s);
  const std::size_t i = static_cast<std::size_t>(it - arcLengthAt_.begin()) - 1;
  const geometry::Vec2 from = waypoints_[i];
  const geometry::Vec2 to = waypoints_[(i + 1) % waypoints_.size()];
  const double legLength = geometry::distance(from, to);
  if (legLength == 0.0) return from;  // repeated waypoint
  return geometry::lerp(from, to, (s - arcLengthAt_[i]) / legLength);
}

}  // namespace camcov::kinematics
