#pragma once
// What one camera knows of the targets and obstacles under limited knowledge (docs/method.md,
// "What a camera knows"): each object as it was when last seen — by the camera itself or by
// whoever told it — with that time. Kept per camera, so that a method of one camera can read
// its own; their union (of each object the entry seen last) is what the team knows, which the
// centralized methods read (TeamKnowledge::known()).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "control/controller.h"
#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "kinematics/world.h"

namespace camcov::sim {

enum class ObjectKind : std::uint8_t { target, obstacle };

// One target or obstacle as it was when last seen.
struct KnownObject {
  ObjectKind kind = ObjectKind::target;
  std::uint32_t id = 0;  // the scene's index of the object (kinematics::targetId, obstacleId)
  geometry::Ring shape;  // world coordinates: its pose and shape when seen
  // Of its bounding box's centre over the step before it was seen, m/s (zero where it was not
  // present one step before): what a method may carry it on with.
  geometry::Vec2 velocity;
  double seenAt = 0.0;              // s
  std::vector<double> edgeWeights;  // a target's importance weights when seen; empty: none
};

class Knowledge {
 public:
  // The camera sees `object` now: its entry is replaced.
  void see(const KnownObject& object);
  // What a message tells: an entry replaces the one known only if it was seen later. Fastest
  // when `told` is in objects() order, as messages are: one walk along both.
  void hear(std::span<const KnownObject> told);
  // Every object known, targets then obstacles, each by ascending id.
  std::span<const KnownObject> objects() const { return objects_; }
  const KnownObject* find(ObjectKind kind, std::uint32_t id) const;
  // What a message tells of camera `teammate` (its pose and goal at `news.sentAt`, from itself
  // or passed on): kept where it is later than the latest known of it.
  void hearTeammate(std::size_t teammate, const control::HeardTeammate& news);
  // Teammates as last heard, by camera index (none: never heard); may be shorter than the team.
  std::span<const std::optional<control::HeardTeammate>> teammates() const { return teammates_; }

 private:
  // Replaces or inserts `object` at `at`, the place of its kind and id (an entry replaced keeps
  // its buffers: no allocation); `onlyIfNewer`: keeps an entry seen at the same time or later.
  void put(std::size_t at, const KnownObject& object, bool onlyIfNewer);
  // Where an entry of `kind` and `id` is or would go.
  std::size_t placeOf(ObjectKind kind, std::uint32_t id) const;
  std::vector<KnownObject> objects_;  // targets then obstacles, by id
  std::vector<std::optional<control::HeardTeammate>> teammates_;
};

// The world a method reads at the instant `now` (the true world: its time, boundary and what
// coverage asks, nothing of its objects): every known object where and as it was last seen (not
// carried on: docs/method.md says why), those never seen absent. Edge weights are carried
// where `weighted` (the true world has them). Written into `out`, whose buffers are reused:
// made again every step for every camera, it allocates only when what is known grows.
void knownWorld(const Knowledge& knowledge, const kinematics::World& now, bool weighted,
                kinematics::World& out);

}  // namespace camcov::sim
