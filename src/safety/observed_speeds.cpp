#include "safety/observed_speeds.h"

#include <algorithm>

namespace camcov::safety {

void ObservedSpeeds::Kind::update(const std::vector<geometry::Ring>& now,
                                  const kinematics::World& world,
                                  std::uint32_t (*idOf)(const kinematics::World&, std::size_t),
                                  double elapsed) {
  speeds.resize(now.size());
  fastest.assign(now.size(), 0.0);
  seenNow.assign(previous.size(), false);
  for (std::size_t i = 0; i < now.size(); ++i) {
    const geometry::Ring& ring = now[i];
    const std::uint32_t id = idOf(world, i);
    if (id >= previous.size()) {
      previous.resize(id + 1);
      lastStep.resize(id + 1);
      seenNow.resize(id + 1, false);
    }
    // Nothing seen before (or absent one step ago), or a ring whose vertex count changed (no
    // correspondence with its past): speed unknown, taken as 0.
    std::vector<double> step(ring.size(), 0.0);
    if (elapsed > 0.0 && previous[id].size() == ring.size()) {
      for (std::size_t v = 0; v < ring.size(); ++v)
        step[v] = geometry::distance(ring[v], previous[id][v]) / elapsed;
    }
    if (lastStep[id].size() != ring.size()) lastStep[id].assign(ring.size(), 0.0);
    speeds[i].resize(ring.size());
    for (std::size_t v = 0; v < ring.size(); ++v) {
      speeds[i][v] = std::max(step[v], lastStep[id][v]);
      fastest[i] = std::max(fastest[i], speeds[i][v]);
    }
    lastStep[id] = std::move(step);
    previous[id] = ring;  // reuses its buffer
    seenNow[id] = true;
  }
  // An object absent now has no past at its next observation.
  for (std::size_t id = 0; id < previous.size(); ++id) {
    if (!seenNow[id]) {
      previous[id].clear();
      lastStep[id].clear();
    }
  }
}

void ObservedSpeeds::observe(const kinematics::World& world) {
  const double elapsed = lastTime_ ? world.time - *lastTime_ : 0.0;
  targets_.update(world.targets, world, kinematics::targetId, elapsed);
  obstacles_.update(world.obstacles, world, kinematics::obstacleId, elapsed);
  lastTime_ = world.time;
}

}  // namespace camcov::safety
