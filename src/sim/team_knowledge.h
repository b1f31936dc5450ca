#pragma once
// Limited knowledge over a run (docs/method.md, "What a camera knows"): at each instant every
// camera sees what its view reaches of the true world, then sends and hears messages
// (communication.h), and the team's union becomes the world the methods read. An object is
// seen by camera j at an instant when some piece of its boundary is visible to j (in visibleBy
// of j) in the sweep of eq. (1) over the true world, with the obstacles' boundaries swept as
// the targets' are: the same occlusion, field of view and sensing range that coverage counts.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "kinematics/world.h"
#include "params/parameters.h"
#include "scene/scene.h"
#include "sim/communication.h"
#include "sim/knowledge.h"
#include "visibility/occluders.h"
#include "visibility/segment.h"
#include "visibility/sweep.h"

namespace camcov::sim {

class TeamKnowledge {
 public:
  // `seed`: the run's, from which the message losses are drawn.
  TeamKnowledge(const scene::Scene& scene, const params::Parameters& params, std::uint64_t seed);
  // The instant of `world`, the true one, with the cameras at `poses` heading for `goals` (as
  // the method last gave them; empty: none): each camera sees, then whoever is due sends, then
  // every message due is heard; known() and own() follow. `measured`: S of `world` for `poses`
  // as the simulator swept it (visibility::Sweep with the scene's lenses), if at hand: in a
  // world without obstacles that is the sweep of every object's boundary, not made again.
  void update(const kinematics::World& world, std::span<const geometry::Pose> poses,
              std::span<const std::optional<geometry::Pose>> goals = {},
              std::optional<std::span<const visibility::Segment>> measured = std::nullopt);
  // What each camera knows, in camera order.
  std::span<const Knowledge> cameras() const { return cameras_; }
  // What the team knows (of each object the entry of cameras() seen last), as the world the
  // centralized methods read.
  const kinematics::World& known() const { return known_; }
  // Whether known() is the true world of the last update, object for object (its time,
  // boundary and what coverage asks are the true world's anyway): as when every object is seen
  // then and none known has gone. Whatever is measured in the one is then measured in the other.
  bool knowsTheWorld() const { return knowsTheWorld_; }
  // What each camera knows on its own, as the world it reads and its teammates as last heard.
  std::span<const control::OwnKnowledge> own() const { return own_; }
  const MessageCounts& messages() const { return communication_.counts(); }
  // Who heard whom at the last update.
  std::span<const Hearing> heard() const { return heard_; }

 private:
  void see(const kinematics::World& world, std::span<const geometry::Pose> poses,
           std::optional<std::span<const visibility::Segment>> measured);
  // Every object's boundary swept as a target's (weights play no part): what each camera sees.
  const std::vector<scene::Lens> lenses_;
  kinematics::World everything_;  // the true world's targets, then its obstacles, as targets
  visibility::Occluders occluders_;
  visibility::Sweep sweep_;
  std::vector<visibility::Segment> segments_;
  std::vector<scene::CameraSet> seenBy_;  // per object of everything_
  KnownObject sighting_;                  // the object seen, as each of its seers keeps it
  Communication communication_;
  std::vector<Knowledge> cameras_;
  // The union of cameras(), kept as it grows: of each object its last sighting by anyone, for
  // whatever a camera knows of an object was seen by someone then, and no later.
  Knowledge team_;
  kinematics::World before_;  // the true world one step before, for the objects' velocities
  bool weighted_ = false;
  kinematics::World known_;
  bool knowsTheWorld_ = false;
  std::vector<control::OwnKnowledge> own_;
  std::span<const Hearing> heard_;
};

}  // namespace camcov::sim
