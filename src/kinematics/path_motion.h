#pragma once
// Motion of an object's reference point along its path (SPEC section 2): the point starts at
// the first waypoint and moves at constant speed through every waypoint and back to the
// first, forever. One waypoint: static. Two: back and forth.
#include <span>
#include <vector>

#include "geometry/vec2.h"

namespace camcov::kinematics {

class PathMotion {
 public:
  PathMotion(std::span<const geometry::Vec2> waypoints, double velocity);

  geometry::Vec2 positionAt(double t) const;
  // Length of one lap of the closed loop, metres (0 for a static object).
  double loopLength() const { return loopLength_; }
  // Time for one lap, seconds (0 for a static object).
  double period() const { return loopLength_ / velocity_; }

 private:
  std::vector<geometry::Vec2> waypoints_;
  std::vector<double> arcLengthAt_;  // arc length from waypoint 0 to waypoint i
  double loopLength_ = 0.0;
  double velocity_ = 1.0;
};

}  // namespace camcov::kinematics
