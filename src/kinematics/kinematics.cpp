#include "kinematics/kinematics.h"

#include <algorithm>
#include <cmath>

#include "kinematics/edge_importance.h"
#include "scene/deformation.h"

namespace camcov::kinematics {

Kinematics::Motion Kinematics::motionOf(const scene::MovingObject& object) {
  Motion m{PathMotion(object.path, object.velocity), std::nullopt};
  if (object.track) m.track.emplace(*object.track);
  return m;
}

Kinematics::Kinematics(const scene::Scene& scene) : scene_(scene) {
  for (const auto& object : scene.targets)
    targetMotion_.push_back(motionOf(object));
  for (const auto& object : scene.obstacles)
    obstacleMotion_.push_back(motionOf(object));
  weighted_ = scene.isWeighted();
}

ObjectPose Kinematics::pose(const scene::MovingObject& object, const Motion& motion, double t) {
  if (motion.track) return {motion.track->positionAt(t), motion.track->headingAt(t)};
  return {motion.path.positionAt(t), object.angularVelocity * t};
}

ObjectPose Kinematics::targetPose(std::size_t i, double t) const {
  return pose(scene_.targets.at(i), targetMotion_.at(i), t);
}

ObjectPose Kinematics::obstaclePose(std::size_t i, double t) const {
  return pose(scene_.obstacles.at(i), obstacleMotion_.at(i), t);
}

void Kinematics::place(const scene::MovingObject& object, const Motion& motion, double t,
                       geometry::Ring& out) {
  const ObjectPose p = pose(object, motion, t);
  if (!object.deformation) {
    // Straight from the shape, not through a copy of it (the simulator's contact search places
    // an object many times a step).
    geometry::placeRing(object.shape, p.angle, p.reference, out);
    return;
  }
  scene::localShapeAt(object, t, out);
  geometry::transformRing(out, p.angle, p.reference);
}

void Kinematics::placeTarget(std::size_t i, double t, geometry::Ring& out) const {
  place(scene_.targets.at(i), targetMotion_.at(i), t, out);
}

void Kinematics::placeObstacle(std::size_t i, double t, geometry::Ring& out) const {
  place(scene_.obstacles.at(i), obstacleMotion_.at(i), t, out);
}

MotionBounds Kinematics::motionBounds(const scene::MovingObject& object, const Motion& motion) {
  double radius = 0.0;
  for (const auto& v : object.shape)
    radius = std::max(radius, geometry::norm(v));
  if (motion.track) return {motion.track->maxSpeed(), radius, motion.track->maxTurnRate(), 0.0};
  // A world point is r(t) + R(ωt)·q(t): its velocity r' + ω R'(ωt) q + R q' is bounded by
  // v + |ω|·|q| + |q'|. Interpolated shapes are convex combinations of the keyframes, so
  // |q| is at most the largest keyframe radius and |q'| the fastest keyframe-to-keyframe step.
  const bool moves = object.path.size() > 1;
  double deformationSpeed = 0.0;
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
  return {moves ? object.velocity : 0.0, radius, std::abs(object.angularVelocity),
          deformationSpeed};
}

MotionBounds Kinematics::targetMotionBounds(std::size_t i) const {
  return motionBounds(scene_.targets.at(i), targetMotion_.at(i));
}

MotionBounds Kinematics::obstacleMotionBounds(std::size_t i) const {
  return motionBounds(scene_.obstacles.at(i), obstacleMotion_.at(i));
}

void Kinematics::worldAt(double t, World& out) const {
  out.time = t;
  out.resolution = scene_.resolution;
  out.boundary.assign(scene_.boundary.begin(), scene_.boundary.end());
  // Rings are reused in place: a ring keeps its buffer when its slot keeps its object.
  const auto fill = [t](const std::vector<scene::MovingObject>& objects,
                        const std::vector<Motion>& motions, std::vector<geometry::Ring>& rings,
                        std::vector<std::uint32_t>& ids) {
    ids.clear();
    for (std::size_t i = 0; i < objects.size(); ++i) {
      if (objects[i].presentAt(t)) ids.push_back(static_cast<std::uint32_t>(i));
    }
    rings.resize(ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k)
      place(objects[ids[k]], motions[ids[k]], t, rings[k]);
  };
  fill(scene_.targets, targetMotion_, out.targets, out.targetIds);
  fill(scene_.obstacles, obstacleMotion_, out.obstacles, out.obstacleIds);
  out.targetEdgeWeights.resize(weighted_ ? out.targets.size() : 0);
  for (std::size_t k = 0; k < out.targetEdgeWeights.size(); ++k) {
    const std::size_t i = out.targetIds[k];
    edgeWeightsAt(scene_.targets[i], out.targets[k], targetMotion(i, t), out.targetEdgeWeights[k]);
  }
  normalizeWeights(out.targetEdgeWeights);
}

std::optional<geometry::Vec2> Kinematics::targetMotion(std::size_t i, double t) const {
  const scene::MovingObject& target = scene_.targets[i];
  if (!target.front) return std::nullopt;
  const auto referenceAt = [&](double when) {
    return pose(target, targetMotion_[i], when).reference;
  };
  return recentMotion(referenceAt, t, target.track ? target.track->start() : 0.0);
}

World Kinematics::worldAt(double t) const {
  World world;
  worldAt(t, world);
  return world;
}

}  // namespace camcov::kinematics
