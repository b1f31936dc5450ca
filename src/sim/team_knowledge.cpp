#include "sim/team_knowledge.h"

#include <algorithm>

#include "control/motion_watch.h"

namespace camcov::sim {

TeamKnowledge::TeamKnowledge(const scene::Scene& scene, const params::Parameters& params,
                             std::uint64_t seed)
    : lenses_(scene::lenses(scene)),
      communication_(params.comms, params.sim.dt, scene.cameras.size(), seed),
      cameras_(scene.cameras.size()),
      weighted_(scene.isWeighted()),
      own_(scene.cameras.size()) {}

void TeamKnowledge::see(const kinematics::World& world, std::span<const geometry::Pose> poses,
                        std::optional<std::span<const visibility::Segment>> measured) {
  const std::size_t targets = world.targets.size();
  const std::size_t objects = targets + world.obstacles.size();
  seenBy_.assign(objects, {});
  if (measured && world.obstacles.empty()) {
    // The sweep below would be of this very arrangement (Occluders reads the boundary and the
    // rings, nothing else), so its segments would be these.
    for (const visibility::Segment& s : *measured)
      seenBy_[s.target] |= s.visibleBy;
  } else {
    // One sweep of every object's boundary: targets first, then obstacles, as targets.
    // Assigned over the last instant's rings, which keep their buffers.
    everything_.time = world.time;
    everything_.boundary = world.boundary;
    everything_.targets.resize(objects);
    std::copy(world.targets.begin(), world.targets.end(), everything_.targets.begin());
    std::copy(world.obstacles.begin(), world.obstacles.end(),
              everything_.targets.begin() + static_cast<std::ptrdiff_t>(targets));
    occluders_.build(everything_);
    sweep_.segments(occluders_, poses, lenses_, segments_);
    for (const visibility::Segment& s : segments_)
      seenBy_[s.target] |= s.visibleBy;
  }

  const std::vector<geometry::Vec2> targetVelocity = control::targetVelocities(world, before_);
  const std::vector<geometry::Vec2> obstacleVelocity = control::obstacleVelocities(world, before_);
  for (std::size_t i = 0; i < objects; ++i) {
    if (seenBy_[i].empty()) continue;
    const bool isTarget = i < targets;
    KnownObject& object = sighting_;
    object.kind = isTarget ? ObjectKind::target : ObjectKind::obstacle;
    object.id =
        isTarget ? kinematics::targetId(world, i) : kinematics::obstacleId(world, i - targets);
    object.shape = isTarget ? world.targets[i] : world.obstacles[i - targets];
    object.velocity = isTarget ? targetVelocity[i] : obstacleVelocity[i - targets];
    object.seenAt = world.time;
    if (isTarget && weighted_ && i < world.targetEdgeWeights.size())
      object.edgeWeights = world.targetEdgeWeights[i];
    else
      object.edgeWeights.clear();
    seenBy_[i].forEach([&](std::size_t j) { cameras_[j].see(object); });
    team_.see(object);
  }
  before_ = world;
}

void TeamKnowledge::update(const kinematics::World& world, std::span<const geometry::Pose> poses,
                           std::span<const std::optional<geometry::Pose>> goals,
                           std::optional<std::span<const visibility::Segment>> measured) {
  see(world, poses, measured);
  communication_.send(world.time, poses, cameras_, goals);
  heard_ = communication_.deliver(world.time, cameras_);
  knownWorld(team_, world, weighted_, known_);
  knowsTheWorld_ = known_.targets == world.targets && known_.targetIds == world.targetIds &&
                   known_.obstacles == world.obstacles && known_.obstacleIds == world.obstacleIds &&
                   known_.targetEdgeWeights == world.targetEdgeWeights;
  for (std::size_t j = 0; j < cameras_.size(); ++j) {
    knownWorld(cameras_[j], world, weighted_, own_[j].world);
    const auto heard = cameras_[j].teammates();
    own_[j].teammates.assign(heard.begin(), heard.end());
    own_[j].teammates.resize(cameras_.size());
  }
}

}  // namespace camcov::sim
