#pragma once
// reward(T, O, C), eq. (8), evaluated many times at one instant: the optimizers and the
// planner call it thousands of times per step, so the per-instant work (the occluder
// arrangement, the perimeter) is done once in setWorld() and every buffer is reused.
// One RewardModel per thread.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "kinematics/world.h"
#include "kinematics/world_simplification.h"
#include "params/parameters.h"
#include "reward/incremental_repulsion.h"
#include "reward/incremental_terms.h"
#include "reward/metrics.h"
#include "visibility/occluders.h"
#include "visibility/sweep.h"

namespace camcov::reward {

class RewardModel {
 public:
  // Camera j of every evaluated team has lens lenses[j] (θ_j, …: scene::lenses()).
  RewardModel(const params::RewardParams& params, std::vector<scene::Lens> lenses);
  // For teams of like cameras (up to scene::kMaxCameras), every one with `lens`.
  RewardModel(const params::RewardParams& params, scene::Lens lens);

  // The instant to evaluate at. The world is copied: callers may change theirs afterwards. A
  // world with the same rings and edge weights, to the bit, as the last one keeps its occluder
  // arrangement (Occluders::buildId()), and with it the sweeps and terms kept for it.
  void setWorld(const kinematics::World& world);
  // The instant `measured` is at, sharing its occluder arrangement (built once per instant)
  // and the sweeps it has made (a camera at a pose it measured is not swept again): how a
  // method takes the simulator's instant (control::Observation::measured). `measured` may
  // change afterwards; what is shared stays as it was.
  void setInstant(const RewardModel& measured);
  // Finely drawn targets and obstacles are judged simplified to within `tolerance`, metres
  // (kinematics/world_simplification.h), from the next instant on; 0, the default: as drawn.
  // world() is then the simplified world. setInstant() of a model with another tolerance takes
  // its world simplified by this one's (shared still where that leaves every ring as it is).
  void setDetail(double tolerance) { detail_ = tolerance; }
  const kinematics::World& world() const { return world_; }
  const visibility::Occluders& occluders() const { return *occluders_; }
  const scene::Lens& lens(std::size_t camera) const { return lenses_[camera]; }
  // length(∂T) at this instant, and the bounding box of every target, then of every obstacle.
  double perimeter() const { return perimeter_; }
  // What the reward's coverage (coverageTerm()) divides by, and each target edge's part in it
  // (global numbering, Occluders::targetEdgeOffset): the weighted perimeter and the edges'
  // importance weights, or the plain perimeter and 1 when the world or the parameters are
  // unweighted.
  double rewardPerimeter() const;
  double rewardWeight(std::uint32_t globalEdge) const {
    return rewardWeighted() ? weights_[globalEdge] : 1.0;
  }
  std::span<const geometry::Box> objectBoxes() const { return objectBoxes_; }
  const params::RewardParams& params() const { return params_; }

  // All terms for the camera set (camera j has lens j; at most as many as there are lenses); S is
  // kept and readable through segments() until the next call.
  RewardTerms evaluate(std::span<const geometry::Pose> cameras);
  // evaluate(cameras)'s terms to the bit, for the optimizers' probes: from the terms kept of
  // the last call (IncrementalTerms), without making S; segments() still holds the last
  // evaluate()'s.
  RewardTerms terms(std::span<const geometry::Pose> cameras);
  double reward(std::span<const geometry::Pose> cameras) { return terms(cameras).reward; }
  std::span<const visibility::Segment> segments() const { return segments_; }
  // Of the team of the last terms() call (not counting resolution) without camera j: what stays
  // while an optimizer probes camera j's poses (AddedCameraBound::prepareMoving). Each target
  // edge's length the others see, unweighted, into `seen` (global numbering), their angles as
  // utilizationOf() sums them, Σ_{i≠j} (θ_0/θ_i)·angles_i, and their repulsion eq. (6).
  struct Others {
    double angles = 0.0;
    double repulsion = 0.0;
  };
  Others othersThan(std::size_t j, std::vector<double>& seen) const;
  // The reward's coverage is resolution-aware (RewardParams::resolution, in a world with a
  // requirement): terms() then measures S whole, and a camera's added coverage is no longer
  // bounded by what the team leaves unseen (AddedCameraBound does not apply).
  bool countsResolution() const { return params_.resolution && world_.resolution.has_value(); }

  // Omnidirectional visibility polygon of a point at this instant (Algorithm 2, line 6).
  void visibilityPolygon(geometry::Vec2 point, geometry::Ring& out);

 private:
  // The reward weighs the edges: RewardParams::weighted, in a world with weights.
  bool rewardWeighted() const { return params_.weighted && !weights_.empty(); }
  // setWorld() of the world as this model judges it.
  void take(const kinematics::World& world);
  // Whether `world` as this model judges it is a simplified drawing of it, then in simplified_:
  // with a detail set and a ring fine enough to lose a vertex (most worlds have none, and are
  // not copied to find that out).
  bool simplify(const kinematics::World& world);
  // Every term of eq. (8) from S.
  RewardTerms termsOf(std::span<const visibility::Segment> segments,
                      std::span<const geometry::Pose> cameras);

  params::RewardParams params_;
  std::vector<scene::Lens> lenses_;
  kinematics::World world_;
  double detail_ = 0.0;  // setDetail()
  kinematics::World simplified_;
  kinematics::SimplificationScratch simplification_;
  double perimeter_ = 0.0;
  std::vector<double> weights_;  // World::targetEdgeWeights by global edge; empty: unweighted
  double weightedPerimeter_ = 0.0;
  std::vector<geometry::Box> objectBoxes_;            // for repulsion()
  std::shared_ptr<visibility::Occluders> occluders_;  // shared by setInstant()
  visibility::Sweep sweep_;
  std::vector<visibility::Segment> segments_;       // S of the last evaluate()
  std::vector<visibility::Segment> probeSegments_;  // S of the last terms() counting resolution
  IncrementalTerms incremental_;                    // for reward()
  IncrementalRepulsion repulsion_;                  // for reward()
};

}  // namespace camcov::reward
