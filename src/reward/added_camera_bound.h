#pragma once
// An upper bound, without a sweep, of the reward eq. (8) of a team with one camera added:
// what lets Algorithm 2 skip the sweeps of samples that cannot be the best. Scoring
// the K samples of one camera is most of the paper method's time on a large crowd, and most
// samples score well below the best.
//
// The added camera q, with half-angle θ_q, at the team's instant:
//  - coverage, eq. (3), weighted as the reward weighs it: q adds at most what the team leaves
//    unseen (times each edge's weight) of the target edges q may
//    see — those of targets whose disc (about their box's centre) meets q's field of view,
//    facing q (a point on an edge's solid side sees nothing of it, as the sweep decides).
//    Occlusion is ignored.
//  - utilization, eq. (5): q's angle sum is at most 2θ_q, and at most the sum of the angles
//    those targets subtend at q (the runs a camera sees never overlap in angle).
//  - repulsion, eq. (6): the team's, plus q's terms with the team and (Fine) the objects, all
//    ≥ 0.
// So bound(q) ≥ reward(team ∪ {q}), with slack for rounding (the sums are taken in another
// order than the reward's): a sample whose bound is below a score already taken is not the
// first best. λ1, λ2, λ3 ≥ 0 (params::validate). Cost: O(N) disc tests and O(n_q) edges for the
// n_q edges of the targets in view, against a sweep's O(n_q log n_q) and its bookkeeping.
//
// Moving camera j of a team is adding it, as camera j with θ_j, to the others
// (prepareMoving): "the team" above is then the others, and M stays the team's size. Our
// method's transit yaws turn a camera in place through 16 directions, most of them away from
// what it could add: those are bounded at O(1) a target (placeAt, ofYaw) and not swept.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "reward/metrics.h"
#include "reward/reward_model.h"

namespace camcov::reward {

class AddedCameraBound {
 public:
  // Prepares for adding a camera (index team.size()) to `team`, whose terms `teamTerms` and S
  // (model.segments()) are those of the model's last evaluate(team).
  void prepare(const RewardModel& model, std::span<const geometry::Pose> team,
               const RewardTerms& teamTerms);
  // Prepares for moving camera j of `team` (θ_j, M = team.size()), the others staying: the
  // bound of the reward of `team` with camera j at the pose given, from what the others see
  // in the model's last terms() call, which must have been of `team` with camera j anywhere
  // (RewardModel::othersThan). The same bound as prepare()'s, of the others with q added as
  // camera j.
  void prepareMoving(const RewardModel& model, std::span<const geometry::Pose> team, std::size_t j);
  // Coarse: q's angle sum bounded by the discs that hold the targets in view, and q's own
  // repulsion terms taken as 0 — O(1) a target. Fine: also by the angles the facing edges
  // subtend, with q's terms against the objects — an atan2 an edge, and O(N + obstacles).
  enum class Precision { Coarse, Fine };
  // At least reward(team ∪ {camera}) of the prepared model and team. `terms` is a buffer (one
  // per thread).
  double of(const geometry::Pose& camera, Precision precision, std::vector<double>& terms) const;
  // The fine bound for a camera turning in place at p (the transit's yaws): what does not
  // depend on the yaw — what q may add of each target and the angle it may take there, q's
  // repulsion — is taken once by placeAt(p), and ofYaw() adds the targets in view, O(1) each.
  void placeAt(geometry::Vec2 p, std::vector<double>& terms);
  double ofYaw(double yaw) const;
  // True when a sample bounded by `bound` cannot beat the score `best`, rounding included.
  static bool cannotBeat(double bound, double best);

 private:
  struct Target {
    std::uint32_t firstEdge = 0, edgeCount = 0;
    int solidSide = 0;      // +1: interior left of each edge (CCW), −1: right, 0: degenerate
    geometry::Vec2 center;  // of its bounding box
    double radius = 0.0;    // of the disc about it that holds the target
    double unseen = 0.0;    // Σ of its edges' unseen lengths
    // At least the angle the target subtends at p (so at least the sum of the angles of the
    // runs a camera at p sees of it, which never overlap).
    double maxAngleFrom(geometry::Vec2 p) const;
  };
  struct Edge {
    geometry::Vec2 a, b;
    double length = 0.0;    // times its weight in the reward (RewardModel::rewardWeight)
    double unseen = 0.0;    // its length less what the team sees of it, weighted the same
    bool hasTwins = false;  // shared with another ring: the sweep keeps it whatever the side
  };

  // What q at p may add of target t's edges (weighted, their unseen lengths) to `gain`, and
  // at most the angle it sees of the target to `angles`.
  void addShare(const Target& t, geometry::Vec2 p, bool fine, double& gain, double& angles) const;
  // The team's repulsion and q's at p: with the objects' terms when fine, else those as 0.
  double repulsionAt(geometry::Vec2 p, bool fine, std::vector<double>& terms) const;
  // The reward's bound from q's coverage gain, its angle sum and the repulsion.
  double combined(double gain, double angles, double repulsion) const;
  // The targets' and edges' geometry at the model's instant, kept while it stays the same.
  void takeInstant(const RewardModel& model);
  // The model's instant, and q as camera `camera` of a team of `cameras` (q included).
  void takeCamera(const RewardModel& model, std::size_t camera, std::size_t cameras);
  // What the team without q sees, weighted: nothing, then `seen` more of edge `edge`, call by
  // call, then the targets' sums.
  void clearSeen();
  void see(std::uint32_t edge, double seen) {
    edges_[edge].unseen -= seen;
    teamSeen_ += seen;
  }
  void sumUnseen();

  std::uint64_t build_ = 0;  // Occluders::buildId() of targets_ and edges_; 0: none
  const RewardModel* model_ = nullptr;
  std::span<const geometry::Pose> others_;  // the team without q
  std::vector<geometry::Pose> othersOfMoving_;
  std::vector<double> seenByOthers_;  // prepareMoving()'s, by global edge
  std::size_t cameraCount_ = 0;       // M, q included
  double halfFov_ = 0.0;              // θ_q
  double theta0_ = 0.0;               // θ_0, of the team's first camera (q's, in an empty team)
  double weight_ = 0.0;               // θ_0/θ_q, its weight in utilizationOf
  double teamSeen_ = 0.0;             // vis(S) of the team
  double teamAngles_ = 0.0;           // Σ_j (θ_0/θ_j)·angles_j of the team
  double teamRepulsion_ = 0.0;
  std::vector<Target> targets_;
  std::vector<Edge> edges_;
  struct Share {
    double gain = 0.0, angles = 0.0;
  };
  geometry::Vec2 placed_;      // placeAt()'s p
  std::vector<Share> shares_;  // by target, at placed_
  double placedRepulsion_ = 0.0;
};

}  // namespace camcov::reward
