#include "sim/knowledge.h"

#include <algorithm>
#include <tuple>

namespace camcov::sim {
namespace {

bool before(const KnownObject& a, ObjectKind kind, std::uint32_t id) {
  return std::tie(a.kind, a.id) < std::tie(kind, id);
}

}  // namespace

void Knowledge::put(KnownObject object, bool onlyIfNewer) {
  const auto at = std::lower_bound(
      objects_.begin(), objects_.end(), object,
      [](const KnownObject& a, const KnownObject& b) { return before(a, b.kind, b.id); });
  if (at == objects_.end() || at->kind != object.kind || at->id != object.id) {
    objects_.insert(at, std::move(object));
  } else if (!onlyIfNewer || object.seenAt > at->seenAt) {
    *at = std::move(object);
  }
}

void Knowledge::see(KnownObject object) {
  put(std::move(object), false);
}

void Knowledge::hear(std::span<const KnownObject> told) {
  for (const KnownObject& object : told)
    put(object, true);
}

const KnownObject* Knowledge::find(ObjectKind kind, std::uint32_t id) const {
  const auto at = std::lower_bound(objects_.begin(), objects_.end(), 0,
                                   [&](const KnownObject& a, int) { return before(a, kind, id); });
  return at != objects_.end() && at->kind == kind && at->id == id ? &*at : nullptr;
}

std::vector<KnownObject> Knowledge::newestFirst(std::size_t limit) const {
  std::vector<KnownObject> entries = objects_;
  std::stable_sort(entries.begin(), entries.end(),
                   [](const KnownObject& a, const KnownObject& b) { return a.seenAt > b.seenAt; });
  if (limit > 0 && entries.size() > limit) entries.resize(limit);
  return entries;
}

void Knowledge::hearTeammate(std::size_t teammate, const control::HeardTeammate& news) {
  if (teammates_.size() <= teammate) teammates_.resize(teammate + 1);
  std::optional<control::HeardTeammate>& known = teammates_[teammate];
  if (!known || news.sentAt > known->sentAt) known = news;
}

Knowledge unionOf(std::span<const Knowledge> team) {
  Knowledge all;
  for (const Knowledge& camera : team)
    all.hear(camera.objects());
  return all;
}

kinematics::World knownWorld(const Knowledge& knowledge, const kinematics::World& now,
                             bool weighted) {
  kinematics::World world;
  world.time = now.time;
  world.boundary = now.boundary;
  world.resolution = now.resolution;
  for (const KnownObject& object : knowledge.objects()) {
    if (object.kind == ObjectKind::target) {
      world.targets.push_back(object.shape);
      world.targetIds.push_back(object.id);
      if (weighted) world.targetEdgeWeights.push_back(object.edgeWeights);
    } else {
      world.obstacles.push_back(object.shape);
      world.obstacleIds.push_back(object.id);
    }
  }
  return world;
}

}  // namespace camcov::sim
