#include "reward/added_camera_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "visibility/occluders.h"

namespace camcov::reward {
namespace {

// The field of view is widened by this much on each side, so that the sweep's own rounding of
// its rays (its angle keys are 2^-30 of a quarter turn apart) never sees past the bound's cone.
constexpr double kFovSlack = 1e-6;  // radians

// The cone of apex p, axis `yaw`, half-angle θ, widened by kFovSlack; for θ < π/2 a convex
// cone, the meet of two half-planes. Wider cones are not convex: every disc may meet them.
struct ViewCone {
  ViewCone(geometry::Vec2 apex, double yaw, double halfFov) : p(apex) {
    const double widened = halfFov + kFovSlack;
    convex = widened < std::numbers::pi / 2;
    right = {std::cos(yaw - widened), std::sin(yaw - widened)};
    left = {std::cos(yaw + widened), std::sin(yaw + widened)};
  }
  // The disc lies wholly outside the cone: farther than its radius right of the right ray's
  // line or left of the left one's (the rays are unit vectors: cross products are distances).
  bool misses(geometry::Vec2 center, double radius) const {
    if (!convex) return false;
    const geometry::Vec2 c = center - p;
    return geometry::cross(right, c) < -radius || geometry::cross(c, left) < -radius;
  }

  geometry::Vec2 p, right, left;
  bool convex = false;
};

// p lies clearly on the solid side of the edge a → b (the interior on side `solidSide`, +1
// left): the sweep sees nothing of it from there. Points within rounding of the edge's line
// are kept: p's distance to the line must pass 1e-9·(|b − a| + |p − a|), taken squared (and
// the sum's square bounded by twice the sum of squares, which only keeps more edges).
bool facesAway(geometry::Vec2 a, geometry::Vec2 b, geometry::Vec2 p, int solidSide) {
  const geometry::Vec2 edge = b - a, toP = p - a;
  const double side = geometry::cross(edge, toP) * solidSide;
  if (!(side > 0.0)) return false;
  const double edge2 = geometry::dot(edge, edge);
  return side * side > 2e-18 * edge2 * (edge2 + geometry::dot(toP, toP));
}

}  // namespace

double AddedCameraBound::Target::maxAngleFrom(geometry::Vec2 p) const {
  // The target lies in the disc of `radius` about `center`, which subtends 2·asin(r/d) at a
  // point at distance d > r; and asin x ≤ tan(asin x) = x/√(1 − x²).
  const geometry::Vec2 d = center - p;
  const double excess = d.x * d.x + d.y * d.y - radius * radius;
  if (!(excess > 1e-12 * radius * radius)) return std::numbers::pi;
  return 2.0 * radius / std::sqrt(excess);
}

void AddedCameraBound::prepare(const RewardModel& model, std::span<const geometry::Pose> team,
                               const RewardTerms& teamTerms) {
  takeCamera(model, team.size(), team.size() + 1);
  others_ = team;
  // utilizationOf's sum, from its mean: Σ_j (θ_0/θ_j)·angles_j = utilization · 2θ_0 · M.
  teamAngles_ = teamTerms.utilization * (2.0 * theta0_) * static_cast<double>(team.size());
  teamRepulsion_ = teamTerms.repulsion;

  clearSeen();
  const visibility::Occluders& occluders = model.occluders();
  for (const visibility::Segment& s : model.segments()) {
    if (s.visibleBy.empty()) continue;
    const std::uint32_t e = occluders.targetEdgeOffset(s.target) + s.edge;
    see(e, model.rewardWeight(e) * visibility::length(s));
  }
  sumUnseen();
}

void AddedCameraBound::prepareMoving(const RewardModel& model, std::span<const geometry::Pose> team,
                                     std::size_t j) {
  takeCamera(model, j, team.size());
  othersOfMoving_.assign(team.begin(), team.end());
  othersOfMoving_.erase(othersOfMoving_.begin() + static_cast<std::ptrdiff_t>(j));
  others_ = othersOfMoving_;
  const RewardModel::Others others = model.othersThan(j, seenByOthers_);
  teamAngles_ = others.angles;
  teamRepulsion_ = others.repulsion;

  clearSeen();
  for (std::uint32_t e = 0; e < seenByOthers_.size(); ++e) {
    if (seenByOthers_[e] > 0.0) see(e, model.rewardWeight(e) * seenByOthers_[e]);
  }
  sumUnseen();
}

void AddedCameraBound::takeCamera(const RewardModel& model, std::size_t camera,
                                  std::size_t cameras) {
  // Another model may weigh the same instant's edges otherwise.
  if (model.occluders().buildId() != build_ || &model != model_) takeInstant(model);
  model_ = &model;
  cameraCount_ = cameras;
  halfFov_ = model.lens(camera).halfFov;
  theta0_ = model.lens(0).halfFov;  // q's own in a team of q alone
  weight_ = utilizationWeight(model.lens(0), model.lens(camera));
}

void AddedCameraBound::clearSeen() {
  for (Edge& edge : edges_)
    edge.unseen = edge.length;
  teamSeen_ = 0.0;
}

void AddedCameraBound::sumUnseen() {
  for (Target& t : targets_) {
    t.unseen = 0.0;
    for (std::uint32_t e = t.firstEdge; e < t.firstEdge + t.edgeCount; ++e) {
      edges_[e].unseen = std::max(edges_[e].unseen, 0.0);
      t.unseen += edges_[e].unseen;
    }
  }
}

void AddedCameraBound::takeInstant(const RewardModel& model) {
  const kinematics::World& world = model.world();
  const visibility::Occluders& occluders = model.occluders();
  build_ = occluders.buildId();
  targets_.resize(occluders.targetCount());
  for (std::uint32_t i = 0; i < occluders.targetCount(); ++i) {
    Target& t = targets_[i];
    const geometry::Box& box = model.objectBoxes()[i];
    t.firstEdge = occluders.targetEdgeOffset(i);
    t.edgeCount = occluders.targetEdgeOffset(i + 1) - t.firstEdge;
    t.center = (box.min + box.max) * 0.5;
    t.radius = 0.0;
    for (const geometry::Vec2 v : world.targets[i])
      t.radius = std::max(t.radius, geometry::distance(v, t.center));
    t.radius *= 1.0 + 1e-12;  // the distances' rounding
    const double area = geometry::signedArea(world.targets[i]);
    t.solidSide = area > 0.0 ? 1 : area < 0.0 ? -1 : 0;
  }
  edges_.resize(occluders.targetEdgeCount());
  for (std::uint32_t e = 0; e < occluders.targetEdgeCount(); ++e) {
    Edge& edge = edges_[e];
    edge.a = occluders.targetEdgeStart(e);
    edge.b = occluders.targetEdgeEnd(e);
    edge.length = model.rewardWeight(e) * geometry::distance(edge.a, edge.b);
    edge.hasTwins = false;
  }
  for (std::uint32_t piece = 0; piece < occluders.pieceCount(); ++piece) {
    const std::uint32_t e = occluders.globalEdge(piece);
    if (e != visibility::Occluders::kNoEdge && occluders.hasTwins(piece)) edges_[e].hasTwins = true;
  }
}

void AddedCameraBound::addShare(const Target& t, geometry::Vec2 p, bool fine, double& gain,
                                double& angles) const {
  const double disc = t.maxAngleFrom(p);
  if (!fine && t.unseen == 0.0) {  // nothing to add to coverage: no edge to look at
    angles += disc;
    return;
  }
  double edgeAngles = 0.0;
  for (std::uint32_t e = t.firstEdge; e < t.firstEdge + t.edgeCount; ++e) {
    const Edge& edge = edges_[e];
    if (!edge.hasTwins && t.solidSide != 0 && facesAway(edge.a, edge.b, p, t.solidSide)) continue;
    gain += edge.unseen;
    if (fine) edgeAngles += subtendedAngle(edge.a, edge.b, p);
  }
  angles += fine ? std::min(disc, edgeAngles) : disc;
}

double AddedCameraBound::repulsionAt(geometry::Vec2 p, bool fine,
                                     std::vector<double>& terms) const {
  const params::RewardParams& params = model_->params();
  double repulsion = teamRepulsion_;
  if (fine) {
    for (const double term :
         objectTerms(model_->world(), model_->objectBoxes(), p, params.d2, terms))
      repulsion += term;
  }
  for (const geometry::Pose& other : others_)
    repulsion += pairTerm(other.position(), p, params.d2);
  return repulsion;
}

double AddedCameraBound::combined(double gain, double angles, double repulsion) const {
  const double coverage = coverageOf(teamSeen_ + gain, model_->rewardPerimeter());
  const double cameraAngles = weight_ * std::min(2.0 * halfFov_, angles);
  const double utilization =
      (teamAngles_ + cameraAngles) / (2.0 * theta0_) / static_cast<double>(cameraCount_);
  const double bound = combine(model_->params(), coverage, utilization, repulsion);
  // No bound at all rather than NaN, which would neither order the samples nor skip one.
  return std::isnan(bound) ? std::numeric_limits<double>::infinity() : bound;
}

double AddedCameraBound::of(const geometry::Pose& camera, Precision precision,
                            std::vector<double>& terms) const {
  const bool fine = precision == Precision::Fine;
  const geometry::Vec2 p = camera.position();
  const ViewCone view(p, camera.yaw, halfFov_);
  double gain = 0.0, angles = 0.0;
  for (const Target& t : targets_) {
    if (!view.misses(t.center, t.radius)) addShare(t, p, fine, gain, angles);
  }
  return combined(gain, angles, repulsionAt(p, fine, terms));
}

void AddedCameraBound::placeAt(geometry::Vec2 p, std::vector<double>& terms) {
  placed_ = p;
  shares_.resize(targets_.size());
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    shares_[i] = {};
    addShare(targets_[i], p, true, shares_[i].gain, shares_[i].angles);
  }
  placedRepulsion_ = repulsionAt(p, true, terms);
}

double AddedCameraBound::ofYaw(double yaw) const {
  const ViewCone view(placed_, yaw, halfFov_);
  double gain = 0.0, angles = 0.0;
  for (std::size_t i = 0; i < targets_.size(); ++i) {
    if (view.misses(targets_[i].center, targets_[i].radius)) continue;
    gain += shares_[i].gain;
    angles += shares_[i].angles;
  }
  return combined(gain, angles, placedRepulsion_);
}

bool AddedCameraBound::cannotBeat(double bound, double best) {
  // The bound and the scores are sums of the same terms in other orders and roundings: far
  // within a billionth of the reward's scale.
  return bound < best - 1e-9 * std::max({1.0, std::abs(best), std::abs(bound)});
}

}  // namespace camcov::reward
