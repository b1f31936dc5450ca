#include "reward/reward_model.h"

#include <utility>

namespace camcov::reward {

RewardModel::RewardModel(const params::RewardParams& params, std::vector<scene::Lens> lenses)
    : params_(params), lenses_(std::move(lenses)) {}

RewardModel::RewardModel(const params::RewardParams& params, scene::Lens lens)
    : RewardModel(params, std::vector<scene::Lens>(scene::kMaxCameras, lens)) {}

void RewardModel::setWorld(const kinematics::World& world) {
  world_ = world;
  perimeter_ = targetPerimeter(world_);
  objectBoxes_ = reward::objectBoxes(world_);
  // A new arrangement, unless this model alone holds its last one: then its buffers are reused.
  if (!occluders_ || occluders_.use_count() > 1)
    occluders_ = std::make_shared<visibility::Occluders>();
  occluders_->build(world_);
  repulsion_.reset();
}

void RewardModel::setInstant(const RewardModel& measured) {
  world_ = measured.world_;
  perimeter_ = measured.perimeter_;
  objectBoxes_ = measured.objectBoxes_;
  occluders_ = measured.occluders_;
  sweep_.keepSweepsOf(measured.sweep_);
  repulsion_.reset();
}

RewardTerms RewardModel::evaluate(std::span<const geometry::Pose> cameras) {
  sweep_.segments(*occluders_, cameras, lenses_, segments_);
  RewardTerms t;
  t.coverage = coverage(segments_, perimeter_);
  t.utilization = utilization(segments_, cameras, lenses_);
  t.repulsion = repulsion(world_, objectBoxes_, cameras, params_.d2);
  t.reward = combine(params_, t.coverage, t.utilization, t.repulsion);
  return t;
}

RewardTerms RewardModel::terms(std::span<const geometry::Pose> cameras) {
  const auto kept = incremental_.evaluate(*occluders_, sweep_, cameras, lenses_, perimeter_);
  RewardTerms t;
  t.coverage = kept.coverage;
  t.utilization = kept.utilization;
  t.repulsion = repulsion_.evaluate(world_, objectBoxes_, cameras, params_.d2);
  t.reward = combine(params_, t.coverage, t.utilization, t.repulsion);
  return t;
}

void RewardModel::visibilityPolygon(geometry::Vec2 point, geometry::Ring& out) {
  sweep_.visibilityPolygon(*occluders_, point, out);
}

}  // namespace camcov::reward
