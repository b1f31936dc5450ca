#include "scene/camera.h"

#include <algorithm>
#include <cmath>

namespace camcov::scene {

bool CameraCommand::isFinite() const {
  return std::isfinite(velocity.x) && std::isfinite(velocity.y) && std::isfinite(angularVelocity);
}

CameraCommand CameraSpec::saturate(CameraCommand u) const {
  if (!std::isfinite(u.velocity.x) || !std::isfinite(u.velocity.y)) u.velocity = {};
  if (!std::isfinite(u.angularVelocity)) u.angularVelocity = 0.0;
  const double speed = geometry::norm(u.velocity);
  if (speed > maxVelocity) u.velocity = u.velocity * (maxVelocity / speed);
  u.angularVelocity = std::clamp(u.angularVelocity, -maxAngularVelocity, maxAngularVelocity);
  return u;
}

double CameraSpec::travelTime(double length, double turn) const {
  return std::max(length / maxVelocity, std::abs(turn) / maxAngularVelocity);
}

double CameraSpec::travelTime(const geometry::Pose& from, const geometry::Pose& to) const {
  return travelTime(geometry::distance(from.position(), to.position()),
                    geometry::wrapAngle(to.yaw - from.yaw));
}

geometry::Pose moved(const geometry::Pose& pose, const CameraCommand& u, double dt) {
  const geometry::Vec2 p = pose.position() + u.velocity * dt;
  return {p.x, p.y, geometry::wrapAngle(pose.yaw + u.angularVelocity * dt)};
}

}  // namespace camcov::scene
