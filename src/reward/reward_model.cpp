#include "reward/reward_model.h"

namespace camcov::reward {

RewardModel::RewardModel(const params::RewardParams& params, double halfFov)
    : params_(params), halfFov_(halfFov) {}

void RewardModel::setWorld(const kinematics::World& world) {
  world_ = world;
  perimeter_ = targetPerimeter(world_);
  occluders_.build(world_);
}

RewardTerms RewardModel::evaluate(std::span<const geometry::Pose> cameras) {
  sweep_.segments(occluders_, cameras, halfFov_, segments_);
  RewardTerms t;
  t.coverage = coverage(segments_, perimeter_);
  t.utilization = utilization(segments_, cameras, halfFov_);
  t.repulsion = repulsion(world_, cameras, params_.d2);
  t.reward = combine(params_, t.coverage, t.utilization, t.repulsion);
  return t;
}

void RewardModel::visibilityPolygon(geometry::Vec2 point, geometry::Ring& out) {
  sweep_.visibilityPolygon(occluders_, point, out);
}

}  // namespace camcov::reward
