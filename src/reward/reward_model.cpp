#include "reward/reward_model.h"

#include "reward/resolution_coverage.h"

#include <utility>

#include "geometry/same_bits.h"

namespace camcov::reward {

namespace {

template <typename T>
bool sameLists(const std::vector<std::vector<T>>& a, const std::vector<std::vector<T>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!geometry::sameBits(std::span<const T>(a[i]), std::span<const T>(b[i]))) return false;
  }
  return true;
}

// Whether `a` and `b` have the same rings and edge weights to the bit: all that the occluder
// arrangement and the incremental terms kept with it are made of.
bool sameArrangement(const kinematics::World& a, const kinematics::World& b) {
  return geometry::sameBits(std::span<const geometry::Vec2>(a.boundary),
                            std::span<const geometry::Vec2>(b.boundary)) &&
         sameLists(a.targets, b.targets) && sameLists(a.obstacles, b.obstacles) &&
         sameLists(a.targetEdgeWeights, b.targetEdgeWeights);
}

}  // namespace

RewardModel::RewardModel(const params::RewardParams& params, std::vector<scene::Lens> lenses)
    : params_(params), lenses_(std::move(lenses)) {}

RewardModel::RewardModel(const params::RewardParams& params, scene::Lens lens)
    : RewardModel(params, std::vector<scene::Lens>(scene::kMaxCameras, lens)) {}

void RewardModel::setWorld(const kinematics::World& world) {
  take(simplify(world) ? simplified_ : world);
}

bool RewardModel::simplify(const kinematics::World& world) {
  return detail_ > 0.0 && kinematics::hasFinelyDrawnObjects(world) &&
         kinematics::simplifyObjects(world, detail_, simplified_, simplification_);
}

void RewardModel::take(const kinematics::World& world) {
  // A world that has not changed (static objects, the next step) keeps its arrangement, and with
  // it every sweep and kept term made for it: a camera that stays is not swept again.
  const bool keep = occluders_ && sameArrangement(world_, world);
  world_ = world;
  perimeter_ = targetPerimeter(world_);
  weightedPerimeter_ = weightedPerimeter(world_);
  weights_.clear();  // in the order of the targets' edges, as Occluders numbers them
  for (const std::vector<double>& w : world_.targetEdgeWeights)
    weights_.insert(weights_.end(), w.begin(), w.end());
  objectBoxes_ = reward::objectBoxes(world_);
  repulsion_.reset();
  if (keep) return;
  // A new arrangement, unless this model alone holds its last one: then its buffers are reused.
  if (!occluders_ || occluders_.use_count() > 1)
    occluders_ = std::make_shared<visibility::Occluders>();
  occluders_->build(world_);
}

void RewardModel::setInstant(const RewardModel& measured) {
  if (!geometry::sameBits(detail_, measured.detail_) && simplify(measured.world_))
    return take(simplified_);
  world_ = measured.world_;
  perimeter_ = measured.perimeter_;
  weights_ = measured.weights_;
  weightedPerimeter_ = measured.weightedPerimeter_;
  objectBoxes_ = measured.objectBoxes_;
  occluders_ = measured.occluders_;
  sweep_.keepSweepsOf(measured.sweep_);
  repulsion_.reset();
}

RewardTerms RewardModel::evaluate(std::span<const geometry::Pose> cameras) {
  sweep_.segments(*occluders_, cameras, lenses_, segments_);
  return termsOf(segments_, cameras);
}

RewardTerms RewardModel::termsOf(std::span<const visibility::Segment> segments,
                                 std::span<const geometry::Pose> cameras) {
  RewardTerms t;
  t.coverage = coverage(segments, perimeter_);
  t.weightedCoverage = weights_.empty()
                           ? t.coverage
                           : coverageOf(weightedVisibleLength(segments, world_.targetEdgeWeights),
                                        weightedPerimeter_);
  t.resolutionCoverage =
      rewardedResolutionCoverage(params_, world_, segments, cameras, lenses_, perimeter_);
  t.utilization = utilization(segments, cameras, lenses_);
  t.repulsion = repulsion(world_, objectBoxes_, cameras, params_.d2);
  t.reward = combine(params_, coverageTerm(params_, t), t.utilization, t.repulsion);
  return t;
}

RewardTerms RewardModel::terms(std::span<const geometry::Pose> cameras) {
  // Resolved coverage is no sum of what each camera adds (a camera resolves what another
  // only sees): S is made and measured whole, in a buffer of its own so that segments() still
  // holds the last evaluate()'s.
  if (countsResolution()) {
    sweep_.segments(*occluders_, cameras, lenses_, probeSegments_);
    return termsOf(probeSegments_, cameras);
  }
  const auto kept = incremental_.evaluate(*occluders_, sweep_, cameras, lenses_,
                                          {perimeter_, weights_, weightedPerimeter_});
  RewardTerms t;
  t.coverage = kept.coverage;
  t.weightedCoverage = kept.weightedCoverage;
  t.utilization = kept.utilization;
  t.repulsion = repulsion_.evaluate(world_, objectBoxes_, cameras, params_.d2);
  t.reward = combine(params_, coverageTerm(params_, t), t.utilization, t.repulsion);
  return t;
}

RewardModel::Others RewardModel::othersThan(std::size_t j, std::vector<double>& seen) const {
  const auto camera = static_cast<std::uint32_t>(j);
  incremental_.seenWithout(*occluders_, camera, seen);
  return {incremental_.anglesWithout(camera), repulsion_.without(j)};
}

double RewardModel::rewardPerimeter() const {
  return rewardWeighted() ? weightedPerimeter_ : perimeter_;
}

void RewardModel::visibilityPolygon(geometry::Vec2 point, geometry::Ring& out) {
  sweep_.visibilityPolygon(*occluders_, point, out);
}

}  // namespace camcov::reward
