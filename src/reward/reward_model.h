#pragma once
// reward(T, O, C), eq. (8), evaluated many times at one instant: the optimizers and the
// planner call it thousands of times per step, so the per-instant work (the occluder
// arrangement, the perimeter) is done once in setWorld() and every buffer is reused.
// One RewardModel per thread.
#include <span>
#include <vector>

#include "kinematics/world.h"
#include "params/parameters.h"
#include "reward/metrics.h"
#include "visibility/occluders.h"
#include "visibility/sweep.h"

namespace camcov::reward {

class RewardModel {
 public:
  RewardModel(const params::RewardParams& params, double halfFov);

  // The instant to evaluate at. The world is copied: callers may change theirs afterwards.
  void setWorld(const kinematics::World& world);
  const kinematics::World& world() const { return world_; }
  const visibility::Occluders& occluders() const { return occluders_; }
  double halfFov() const { return halfFov_; }
  const params::RewardParams& params() const { return params_; }

  // All terms for the camera set; S is kept and readable through segments() until next call.
  RewardTerms evaluate(std::span<const geometry::Pose> cameras);
  double reward(std::span<const geometry::Pose> cameras) { return evaluate(cameras).reward; }
  std::span<const visibility::Segment> segments() const { return segments_; }

  // Omnidirectional visibility polygon of a point at this instant (Algorithm 2, line 6).
  void visibilityPolygon(geometry::Vec2 point, geometry::Ring& out);

 private:
  params::RewardParams params_;
  double halfFov_;
  kinematics::World world_;
  double perimeter_ = 0.0;
  visibility::Occluders occluders_;
  visibility::Sweep sweep_;
  std::vector<visibility::Segment> segments_;
};

}  // namespace camcov::reward
