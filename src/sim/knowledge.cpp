#include "sim/knowledge.h"

#include <algorithm>
#include <tuple>

namespace camcov::sim {
namespace {

bool before(const KnownObject& a, ObjectKind kind, std::uint32_t id) {
  return std::tie(a.kind, a.id) < std::tie(kind, id);
}

}  // namespace

std::size_t Knowledge::placeOf(ObjectKind kind, std::uint32_t id) const {
  const auto at = std::lower_bound(objects_.begin(), objects_.end(), 0,
                                   [&](const KnownObject& a, int) { return before(a, kind, id); });
  return static_cast<std::size_t>(at - objects_.begin());
}

void Knowledge::put(std::size_t at, const KnownObject& object, bool onlyIfNewer) {
  if (at == objects_.size() || objects_[at].kind != object.kind || objects_[at].id != object.id) {
    objects_.insert(objects_.begin() + static_cast<std::ptrdiff_t>(at), object);
  } else if (!onlyIfNewer || object.seenAt > objects_[at].seenAt) {
    objects_[at] = object;
  }
}

void Knowledge::see(const KnownObject& object) {
  put(placeOf(object.kind, object.id), object, false);
}

void Knowledge::hear(std::span<const KnownObject> told) {
  // Every entry before `at` comes before the one told: while `told` ascends, its place is
  // found by walking on from the last one's.
  std::size_t at = 0;
  for (const KnownObject& object : told) {
    if (at > 0 && !before(objects_[at - 1], object.kind, object.id)) {
      at = placeOf(object.kind, object.id);
    } else {
      while (at < objects_.size() && before(objects_[at], object.kind, object.id))
        ++at;
    }
    put(at, object, true);
  }
}

const KnownObject* Knowledge::find(ObjectKind kind, std::uint32_t id) const {
  const std::size_t at = placeOf(kind, id);
  return at != objects_.size() && objects_[at].kind == kind && objects_[at].id == id ? &objects_[at]
                                                                                     : nullptr;
}

void Knowledge::hearTeammate(std::size_t teammate, const control::HeardTeammate& news) {
  if (teammates_.size() <= teammate) teammates_.resize(teammate + 1);
  std::optional<control::HeardTeammate>& known = teammates_[teammate];
  if (!known || news.sentAt > known->sentAt) known = news;
}

void knownWorld(const Knowledge& knowledge, const kinematics::World& now, bool weighted,
                kinematics::World& out) {
  out.time = now.time;
  out.boundary = now.boundary;
  out.resolution = now.resolution;
  const std::span<const KnownObject> objects = knowledge.objects();
  const auto firstObstacle =
      std::partition_point(objects.begin(), objects.end(),
                           [](const KnownObject& o) { return o.kind == ObjectKind::target; });
  const std::span<const KnownObject> targets(objects.begin(), firstObstacle);
  const std::span<const KnownObject> obstacles(firstObstacle, objects.end());
  // Resized, then assigned in place: a ring assigned over one as long keeps its buffer.
  out.targets.resize(targets.size());
  out.targetIds.resize(targets.size());
  out.targetEdgeWeights.resize(weighted ? targets.size() : 0);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    out.targets[i] = targets[i].shape;
    out.targetIds[i] = targets[i].id;
    if (weighted) out.targetEdgeWeights[i] = targets[i].edgeWeights;
  }
  out.obstacles.resize(obstacles.size());
  out.obstacleIds.resize(obstacles.size());
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    out.obstacles[i] = obstacles[i].shape;
    out.obstacleIds[i] = obstacles[i].id;
  }
}

}  // namespace camcov::sim
