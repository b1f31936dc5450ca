#include "control/motion_watch.h"

#include <algorithm>
#include <utility>

namespace camcov::control {

namespace {

geometry::Vec2 centre(const geometry::Ring& ring) {
  const geometry::Box b = geometry::boundingBox(ring);
  return (b.min + b.max) * 0.5;
}

// Per ring of `now`, the velocity of its centre since `before`, matched by scene id (both id
// lists ascend: the scene's order with the absent left out); 0 for a ring that has just come.
std::vector<geometry::Vec2> velocities(const std::vector<geometry::Ring>& now,
                                       const std::vector<std::uint32_t>& nowIds,
                                       const std::vector<geometry::Ring>& before,
                                       const std::vector<std::uint32_t>& beforeIds, double dt) {
  std::vector<geometry::Vec2> v(now.size(), geometry::Vec2{0.0, 0.0});
  if (!(dt > 0.0)) return v;
  const auto idOf = [](const std::vector<std::uint32_t>& ids, std::size_t i) {
    return ids.empty() ? static_cast<std::uint32_t>(i) : ids[i];
  };
  std::size_t k = 0;
  for (std::size_t i = 0; i < now.size(); ++i) {
    while (k < before.size() && idOf(beforeIds, k) < idOf(nowIds, i))
      ++k;
    if (k < before.size() && idOf(beforeIds, k) == idOf(nowIds, i)) {
      v[i] = (centre(now[i]) - centre(before[k])) * (1.0 / dt);
    }
  }
  return v;
}

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
  const double dt = seen_ < 2 ? 0.0 : last_.time - before_.time;
  return Forecast(
      last_, velocities(last_.targets, last_.targetIds, before_.targets, before_.targetIds, dt),
      velocities(last_.obstacles, last_.obstacleIds, before_.obstacles, before_.obstacleIds, dt),
      room);
}

}  // namespace camcov::control
