#include "kinematics/kinematics.h"

#include "scene/deformation.h"

namespace camcov::kinematics {

Kinematics::Kinematics(const scene::Scene& scene) : scene_(scene) {
  for (const auto& object : scene.targets)
    targetMotion_.emplace_back(object.path, object.velocity);
  for (const auto& object : scene.obstacles) {
    obstacleMotion_.emplace_back(object.path, object.velocity);
  }
}

ObjectPose Kinematics::pose(const scene::MovingObject& object, const PathMotion& motion, double t) {
  return {motion.positionAt(t), object.angularVelocity * t};
}

ObjectPose Kinematics::targetPose(std::size_t i, double t) const {
  return pose(scene_.targets.at(i), targetMotion_.at(i), t);
}

ObjectPose Kinematics::obstaclePose(std::size_t i, double t) const {
  return pose(scene_.obstacles.at(i), obstacleMotion_.at(i), t);
}

void Kinematics::place(const scene::MovingObject& object, const PathMotion& motion, double t,
                       geometry::Ring& out) {
  const ObjectPose p = pose(object, motion, t);
  scene::localShapeAt(object, t, out);
  geometry::transformRing(out, p.angle, p.reference);
}

void Kinematics::worldAt(double t, World& out) const {
  out.time = t;
  out.boundary.assign(scene_.boundary.begin(), scene_.boundary.end());
  out.targets.resize(scene_.targets.size());
  out.obstacles.resize(scene_.obstacles.size());
  for (std::size_t i = 0; i < scene_.targets.size(); ++i) {
    place(scene_.targets[i], targetMotion_[i], t, out.targets[i]);
  }
  for (std::size_t i = 0; i < scene_.obstacles.size(); ++i) {
    place(scene_.obstacles[i], obstacleMotion_[i], t, out.obstacles[i]);
  }
}

World Kinematics::worldAt(double t) const {
  World world;
  worldAt(t, world);
  return world;
}

}  // namespace camcov::kinematics
