#include "control/motion_watch.h"

#include <algorithm>
#include <utility>

namespace camcov::control {

namespace {

geometry::Vec2 centre(const geometry::Ring& ring) {
  const geometry::Box b = geometry::boundingBox(ring);
  return (b.min + b.max) * 0.5;
}

// Per target (`rings` = &World::targets, `idOf` = kinematics::targetId) or obstacle of `now`,
// the velocity of its centre since `before`, matched by scene id (ids ascend: the scene's order
// with the absent left out); 0 for one that has just come.
std::vector<geometry::Vec2> velocities(const kinematics::World& now,
                                       const kinematics::World& before,
                                       std::vector<geometry::Ring> kinematics::World::*rings,
                                       std::uint32_t (*idOf)(const kinematics::World&,
                                                             std::size_t)) {
  const auto& nowRings = now.*rings;
  const auto& beforeRings = before.*rings;
  std::vector<geometry::Vec2> v(nowRings.size());
  const double dt = now.time - before.time;
  if (!(dt > 0.0)) return v;
  std::size_t k = 0;
  for (std::size_t i = 0; i < nowRings.size(); ++i) {
    const std::uint32_t id = idOf(now, i);
    while (k < beforeRings.size() && idOf(before, k) < id)
      ++k;
    if (k < beforeRings.size() && idOf(before, k) == id)
      v[i] = (centre(nowRings[i]) - centre(beforeRings[k])) * (1.0 / dt);
  }
  return v;
}

}  // namespace

std::vector<geometry::Vec2> targetVelocities(const kinematics::World& now,
                                             const kinematics::World& before) {
  return velocities(now, before, &kinematics::World::targets, kinematics::targetId);
}

std::vector<geometry::Vec2> obstacleVelocities(const kinematics::World& now,
                                               const kinematics::World& before) {
  return velocities(now, before, &kinematics::World::obstacles, kinematics::obstacleId);
}

namespace {

void moveOn(std::vector<geometry::Ring>& rings, const std::vector<geometry::Vec2>& velocity,
            double seconds, const geometry::Box& room) {
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if (velocity[i].x == 0.0 && velocity[i].y == 0.0) continue;
    const geometry::Box b = geometry::boundingBox(rings[i]);
    geometry::Vec2 d = velocity[i] * seconds;
    // Stopped at the room's box; one already beyond it moves no farther out.
    d.x = std::clamp(d.x, std::min(0.0, room.min.x - b.min.x), std::max(0.0, room.max.x - b.max.x));
    d.y = std::clamp(d.y, std::min(0.0, room.min.y - b.min.y), std::max(0.0, room.max.y - b.max.y));
    geometry::transformRing(rings[i], 0.0, d);
  }
}

bool anyMoves(const std::vector<geometry::Vec2>& velocity) {
  return std::any_of(velocity.begin(), velocity.end(),
                     [](geometry::Vec2 v) { return v.x != 0.0 || v.y != 0.0; });
}

}  // namespace

Forecast::Forecast(kinematics::World now, std::vector<geometry::Vec2> targetVelocity,
                   std::vector<geometry::Vec2> obstacleVelocity, const geometry::Box& room)
    : now_(std::move(now)),
      targetVelocity_(std::move(targetVelocity)),
      obstacleVelocity_(std::move(obstacleVelocity)),
      room_(room) {}

kinematics::World Forecast::at(double seconds) const {
  kinematics::World w = now_;
  w.time += seconds;
  moveOn(w.targets, targetVelocity_, seconds, room_);
  moveOn(w.obstacles, obstacleVelocity_, seconds, room_);
  return w;
}

bool Forecast::moves() const {
  return anyMoves(targetVelocity_) || anyMoves(obstacleVelocity_);
}

std::optional<bool> MotionWatch::see(const kinematics::World& world) {
  before_ = std::exchange(last_, world);
  seen_ = std::min(seen_ + 1, 2);
  if (seen_ < 2) return std::nullopt;
  return !(last_.targets == before_.targets && last_.obstacles == before_.obstacles &&
           last_.targetIds == before_.targetIds && last_.obstacleIds == before_.obstacleIds);
}

Forecast MotionWatch::forecast(const geometry::Box& room) const {
  if (seen_ < 2) {  // no motion seen yet: everything stands
    return Forecast(last_, std::vector<geometry::Vec2>(last_.targets.size()),
                    std::vector<geometry::Vec2>(last_.obstacles.size()), room);
  }
  return Forecast(last_, targetVelocities(last_, before_), obstacleVelocities(last_, before_),
                  room);
}

}  // namespace camcov::control
