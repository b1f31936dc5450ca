#include "kinematics/kinematics.h"

#include <algorithm>
#include <cmath>

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

void Kinematics::placeTarget(std::size_t i, double t, geometry::Ring& out) const {
  place(scene_.targets.at(i), targetMotion_.at(i), t, out);
}

void Kinematics::placeObstacle(std::size_t i, double t, geometry::Ring& out) const {
  place(scene_.obstacles.at(i), obstacleMotion_.at(i), t, out);
}

double Kinematics::speedBound(const scene::MovingObject& object) {
  // A world point is r(t) + R(ωt)·q(t): its velocity r' + ω R'(ωt) q + R q' is bounded by
  // v + |ω|·|q| + |q'|. Interpolated shapes are convex combinations of the keyframes, so
  // |q| is at most the largest keyframe radius and |q'| the fastest keyframe-to-keyframe step.
  const bool moves = object.path.size() > 1;
  double radius = 0.0, deformationSpeed = 0.0;
  for (const auto& v : object.shape)
    radius = std::max(radius, geometry::norm(v));
  if (object.deformation) {
    const auto& d = *object.deformation;
    const geometry::Ring* from = &object.shape;
    double t0 = 0.0;
    auto step = [&](const geometry::Ring& to, double t1) {
      for (std::size_t k = 0; k < to.size(); ++k) {
        radius = std::max(radius, geometry::norm(to[k]));
        deformationSpeed =
            std::max(deformationSpeed, geometry::distance((*from)[k], to[k]) / (t1 - t0));
      }
      from = &to;
      t0 = t1;
    };
    for (const auto& frame : d.keyframes)
      step(frame.shape, frame.time);
    step(object.shape, d.period);
  }
  return (moves ? object.velocity : 0.0) + std::abs(object.angularVelocity) * radius +
         deformationSpeed;
}

double Kinematics::targetSpeedBound(std::size_t i) const {
  return speedBound(scene_.targets.at(i));
}

double Kinematics::obstacleSpeedBound(std::size_t i) const {
  return speedBound(scene_.obstacles.at(i));
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
