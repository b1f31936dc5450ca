#include "sim/team_knowledge.h"

#include "control/motion_watch.h"

namespace camcov::sim {
namespace {

params::RewardParams unweighted(params::RewardParams p) {
  p.weighted = false;
  return p;
}

}  // namespace

TeamKnowledge::TeamKnowledge(const scene::Scene& scene, const params::Parameters& params,
                             std::uint64_t seed)
    : sight_(unweighted(params.reward), scene::lenses(scene)),
      communication_(params.comms, params.sim.dt, scene.cameras.size(), seed),
      cameras_(scene.cameras.size()),
      weighted_(scene.isWeighted()) {}

void TeamKnowledge::see(const kinematics::World& world, std::span<const geometry::Pose> poses) {
  // One sweep of every object's boundary: targets first, then obstacles, as targets.
  kinematics::World everything;
  everything.time = world.time;
  everything.boundary = world.boundary;
  everything.targets = world.targets;
  everything.targets.insert(everything.targets.end(), world.obstacles.begin(),
                            world.obstacles.end());
  sight_.setWorld(everything);
  sight_.evaluate(poses);
  const std::size_t objects = everything.targets.size();
  std::vector<scene::CameraSet> seenBy(objects);
  for (const visibility::Segment& s : sight_.segments())
    seenBy[s.target] |= s.visibleBy;

  const std::vector<geometry::Vec2> targetVelocity = control::targetVelocities(world, before_);
  const std::vector<geometry::Vec2> obstacleVelocity = control::obstacleVelocities(world, before_);
  const std::size_t targets = world.targets.size();
  for (std::size_t i = 0; i < objects; ++i) {
    if (seenBy[i].empty()) continue;
    const bool isTarget = i < targets;
    KnownObject object;
    object.kind = isTarget ? ObjectKind::target : ObjectKind::obstacle;
    object.id =
        isTarget ? kinematics::targetId(world, i) : kinematics::obstacleId(world, i - targets);
    object.shape = everything.targets[i];
    object.velocity = isTarget ? targetVelocity[i] : obstacleVelocity[i - targets];
    object.seenAt = world.time;
    if (isTarget && weighted_ && i < world.targetEdgeWeights.size())
      object.edgeWeights = world.targetEdgeWeights[i];
    seenBy[i].forEach([&](std::size_t j) { cameras_[j].see(object); });
  }
  before_ = world;
}

void TeamKnowledge::update(const kinematics::World& world, std::span<const geometry::Pose> poses,
                           std::span<const std::optional<geometry::Pose>> goals) {
  see(world, poses);
  communication_.send(world.time, poses, cameras_, goals);
  heard_ = communication_.deliver(world.time, cameras_);
  knownWorld(unionOf(cameras_), world, weighted_, known_);
  own_.resize(cameras_.size());
  for (std::size_t j = 0; j < cameras_.size(); ++j) {
    knownWorld(cameras_[j], world, weighted_, own_[j].world);
    const auto heard = cameras_[j].teammates();
    own_[j].teammates.assign(heard.begin(), heard.end());
    own_[j].teammates.resize(cameras_.size());
  }
}

}  // namespace camcov::sim
