#include "safety/observed_speeds.h"

#include <algorithm>

namespace camcov::safety {

void ObservedSpeeds::Kind::update(const std::vector<geometry::Ring>& now, double elapsed) {
  speeds.resize(now.size());
  lastStep.resize(now.size());
  fastest.assign(now.size(), 0.0);
  for (std::size_t i = 0; i < now.size(); ++i) {
    const geometry::Ring& ring = now[i];
    // Nothing seen before, or a ring whose vertex count changed (no correspondence with its
    // past): speed unknown, taken as 0.
    std::vector<double> step(ring.size(), 0.0);
    if (elapsed > 0.0 && i < previous.size() && previous[i].size() == ring.size()) {
      for (std::size_t v = 0; v < ring.size(); ++v)
        step[v] = geometry::distance(ring[v], previous[i][v]) / elapsed;
    }
    if (lastStep[i].size() != ring.size()) lastStep[i].assign(ring.size(), 0.0);
    speeds[i].resize(ring.size());
    for (std::size_t v = 0; v < ring.size(); ++v) {
      speeds[i][v] = std::max(step[v], lastStep[i][v]);
      fastest[i] = std::max(fastest[i], speeds[i][v]);
    }
    lastStep[i] = std::move(step);
  }
  previous = now;
}

void ObservedSpeeds::observe(const kinematics::World& world) {
  const double elapsed = lastTime_ ? world.time - *lastTime_ : 0.0;
  targets_.update(world.targets, elapsed);
  obstacles_.update(world.obstacles, elapsed);
  lastTime_ = world.time;
}

}  // namespace camcov::safety
