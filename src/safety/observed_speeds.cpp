#include "safety/observed_speeds.h"

#include <algorithm>

namespace camcov::safety {

void ObservedSpeeds::update(const std::vector<geometry::Ring>& now, double elapsed, Kind& kind,
                            std::vector<std::vector<double>>& speeds,
                            std::vector<double>& fastest) {
  speeds.resize(now.size());
  fastest.assign(now.size(), 0.0);
  kind.lastStep.resize(now.size());
  for (std::size_t i = 0; i < now.size(); ++i) {
    const geometry::Ring& ring = now[i];
    auto& last = kind.lastStep[i];
    // A ring whose vertex count changed has no correspondence with its past: unknown, 0.
    const bool comparable = elapsed > 0.0 && i < kind.previous.size() &&
                            kind.previous[i].size() == ring.size() && last.size() == ring.size();
    speeds[i].assign(ring.size(), 0.0);
    std::vector<double> step(ring.size(), 0.0);
    if (elapsed > 0.0 && i < kind.previous.size() && kind.previous[i].size() == ring.size()) {
      for (std::size_t v = 0; v < ring.size(); ++v)
        step[v] = geometry::distance(ring[v], kind.previous[i][v]) / elapsed;
    }
    for (std::size_t v = 0; v < ring.size(); ++v) {
      speeds[i][v] = comparable ? std::max(step[v], last[v]) : step[v];
      fastest[i] = std::max(fastest[i], speeds[i][v]);
    }
    last = std::move(step);
  }
  kind.previous = now;
}

void ObservedSpeeds::observe(const kinematics::World& world) {
  const double elapsed = seen_ ? world.time - lastTime_ : 0.0;
  update(world.targets, elapsed, targetHistory_, targets_, fastestTargets_);
  update(world.obstacles, elapsed, obstacleHistory_, obstacles_, fastestObstacles_);
  seen_ = true;
  lastTime_ = world.time;
}

}  // namespace camcov::safety
