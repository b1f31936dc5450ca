#include "scene/camera.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "geometry/ring.h"
#include "scene/camera_keys.h"

namespace camcov::scene {

bool Lens::sees(geometry::Vec2 offset, double yaw) const {
  const double off = std::abs(geometry::wrapAngle(std::atan2(offset.y, offset.x) - yaw));
  return off <= halfFov && withinRange(geometry::norm(offset));
}

bool Lens::rangeOnSegment(geometry::Vec2 camera, geometry::Vec2 a, geometry::Vec2 b, double& t0,
                          double& t1) const {
  return geometry::discOnSegment(camera, range, a, b, t0, t1);
}

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

nlohmann::json describeCamera(const CameraSpec& camera) {
  nlohmann::json j{{"x", camera.initial.x}, {"y", camera.initial.y}};
  for (const CameraKey& row : kCameraKeys)
    if (row.carried(camera)) j[row.name] = row.toFile(row.get(camera));
  return j;
}

}  // namespace camcov::scene
