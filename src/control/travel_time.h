#pragma once
// How long a camera needs from one pose to another, as section V-B estimates it for the
// assignment: the longer of moving and turning at full speed, obstacles ignored.
#include <algorithm>
#include <cmath>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::control {

// Running `length` m and turning `turn` rad at once, at v_max and γ̇_max.
inline double travelTime(double length, double turn, double maxVelocity,
                         double maxAngularVelocity) {
  return std::max(length / maxVelocity, std::abs(turn) / maxAngularVelocity);
}

inline double travelTime(const scene::CameraSpec& camera, const geometry::Pose& from,
                         const geometry::Pose& to) {
  return travelTime(geometry::distance(from.position(), to.position()),
                    geometry::wrapAngle(to.yaw - from.yaw), camera.maxVelocity,
                    camera.maxAngularVelocity);
}

}  // namespace camcov::control
