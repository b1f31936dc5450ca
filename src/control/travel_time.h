#pragma once
// How long a camera needs from one pose to another, as section V-B estimates it for the
// assignment: the longer of moving and turning at full speed, obstacles ignored.
#include <algorithm>
#include <cmath>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::control {

inline double travelTime(const scene::CameraSpec& camera, const geometry::Pose& from,
                         const geometry::Pose& to) {
  const double travel = geometry::distance(from.position(), to.position()) / camera.maxVelocity;
  const double turn = std::abs(geometry::wrapAngle(to.yaw - from.yaw)) / camera.maxAngularVelocity;
  return std::max(travel, turn);
}

}  // namespace camcov::control
