#pragma once
// The terms of the reward (paper section IV-A) as pure functions of one instant:
// vis(S) eq. (2), coverage eq. (3), utilization eq. (5), repulsion eq. (6)-(7), reward eq. (8).
#include <optional>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "params/parameters.h"
#include "scene/camera.h"
#include "visibility/segment.h"

namespace camcov::reward {

struct RewardTerms {
  double coverage = 0.0;  // eq. (3), in [0, 1]: length seen over length
  // eq. (3) with each metre weighted by its importance (World::targetEdgeWeights): weighted
  // length seen over weighted length. Equal to coverage in a world without weights.
  double weightedCoverage = 0.0;
  double utilization = 0.0;  // eq. (5), in [0, 1]
  double repulsion = 0.0;    // eq. (6), >= 0
  double reward = 0.0;       // eq. (8): λ1·coverage + λ2·utilization − λ3·repulsion, with
                             // the coverage coverageTerm() picks
  // Resolution-aware coverage (resolution_coverage.h), where the reward counts it
  // (RewardModel::countsResolution); else none.
  std::optional<double> resolutionCoverage;
};

// The coverage the reward eq. (8) takes: resolved where the reward counts resolution, else
// weighted unless the parameters say plain. Utilization
// and repulsion are not weighted: one measures how much of a camera's view holds targets at
// all, the other keeps cameras off objects, and neither is about what of a target is seen.
inline double coverageTerm(const params::RewardParams& p, const RewardTerms& t) {
  if (t.resolutionCoverage) return *t.resolutionCoverage;
  return p.weighted ? t.weightedCoverage : t.coverage;
}

// How the sums of eq. (2) and (5) are taken, so that the optimizers' incremental terms
// (incremental_terms.h) give the same numbers to the bit as these functions on S:
//  - vis(S) adds, per target edge, the length of each run of consecutive seen segments (not
//    of each segment), as exact fixed-point sums (fixed_point_sum.h): the same whatever order
//    the runs are added in;
//  - utilization adds, per camera j, the angle ∠ r¹ p_j r² of each run r of consecutive
//    segments j sees, in the order of S (by target edge and along it), then over the cameras
//    in index order.
// The segments of a run lie on one line, so both are the paper's sums over segments.

// vis(S), eq. (2): total length of segments some camera sees.
double visibleLength(std::span<const visibility::Segment> segments);
// length(∂T): sum of the targets' perimeters.
double targetPerimeter(const kinematics::World& world);
// vis(S) and length(∂T) with each edge's length times its weight (weights[target][edge],
// World::targetEdgeWeights), summed as their plain forms are: with every weight 1 the same to
// the bit. Empty weights: the plain forms.
double weightedVisibleLength(std::span<const visibility::Segment> segments,
                             const std::vector<std::vector<double>>& weights);
double weightedPerimeter(const kinematics::World& world);
// Coverage eq. (3) weighted by world.targetEdgeWeights (RewardTerms::weightedCoverage); the
// plain coverage in a world without weights.
double weightedCoverage(std::span<const visibility::Segment> segments,
                        const kinematics::World& world);
// Coverage, eq. (3). 0 when the targets have no boundary length.
double coverage(std::span<const visibility::Segment> segments, double perimeter);
// The same from vis(S).
double coverageOf(double visibleLength, double perimeter);
// Utilization, eq. (5): mean over cameras of the angle ∠ s¹ p_j s² of every segment camera j
// sees, over its field of view 2θ_j (lenses[j]).
double utilization(std::span<const visibility::Segment> segments,
                   std::span<const geometry::Pose> cameras, std::span<const scene::Lens> lenses);
// The angle ∠ a p b that a piece of target boundary from a to b subtends at p, in [0, π].
double subtendedAngle(geometry::Vec2 a, geometry::Vec2 b, geometry::Vec2 p);
// The weight θ_0/θ_j of camera j's angles when eq. (5) is summed over the first camera's 2θ_0
// (`first`: camera 0's lens, `camera`: camera j's): every place that sums utilization weighs by it.
inline double utilizationWeight(const scene::Lens& first, const scene::Lens& camera) {
  return first.halfFov / camera.halfFov;
}
// Utilization from each camera's sum of subtended angles (angles[j]: camera j, θ_j of
// lenses[j]): Σ_j (θ_0/θ_j)·angles[j] / 2θ_0 / M.
double utilizationOf(std::span<const double> angles, std::span<const scene::Lens> lenses);
// Length of the target boundary camera j sees (what it contributes before overlaps).
double visibleLengthOf(std::span<const visibility::Segment> segments, unsigned camera);

// invdist(a, b), eq. (7): 1/dist² closer than d2, else 0. A zero distance (a camera on or in
// an object) is taken as kMinDistance so the reward stays finite and still strongly negative.
inline constexpr double kMinDistance = 1e-3;
double invdist(double distance, double d2);
// Repulsion, eq. (6): every camera against every target and obstacle, and camera pairs; an
// exact fixed-point sum of its terms (fixed_point_sum.h), the same in any order.
double repulsion(const kinematics::World& world, std::span<const geometry::Pose> cameras,
                 double d2);
// The bounding box of every target, then of every obstacle, in World order.
std::vector<geometry::Box> objectBoxes(const kinematics::World& world);
// The same, skipping the objects whose box (objectBoxes(world)) is farther than d2 from a camera:
// their term is 0, so the sum is the same to the bit, without measuring the distance to them.
double repulsion(const kinematics::World& world, std::span<const geometry::Box> boxes,
                 std::span<const geometry::Pose> cameras, double d2);
// The term of eq. (6) between two cameras at a and b: invdist(‖a − b‖, d2).
double pairTerm(geometry::Vec2 a, geometry::Vec2 b, double d2);
// The terms of eq. (6) between a camera at p and the objects, every target then every obstacle
// in World order, that may be nonzero (those whose box is within d2): the others are 0.
std::vector<double>& objectTerms(const kinematics::World& world,
                                 std::span<const geometry::Box> boxes, geometry::Vec2 p, double d2,
                                 std::vector<double>& out);
// Camera j's own terms, as if it were alone: eq. (3) over what it sees of S (`segments`, made
// for `cameras`), eq. (5) with M = 1, eq. (6) against the objects and the other cameras, and
// eq. (8) of those. What the explorer, the playground and the learning environments show a
// camera's share as.
RewardTerms termsAlone(const kinematics::World& world,
                       std::span<const visibility::Segment> segments,
                       std::span<const geometry::Pose> cameras, std::span<const scene::Lens> lenses,
                       std::size_t j, const params::RewardParams& params);
// Reward, eq. (8).
double combine(const params::RewardParams& p, double coverage, double utilization,
               double repulsion);
// The most eq. (8) gives where coverage and utilization are at most 1 and repulsion is not
// negative: λ1 + λ2, each where positive; +∞ where λ3 < 0 (repulsion then adds). Utilization
// passes 1 only where two targets share a seen edge (each counts the edge's angle).
double rewardCeiling(const params::RewardParams& p);

}  // namespace camcov::reward
