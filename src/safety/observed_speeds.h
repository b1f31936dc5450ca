#pragma once
// How fast each vertex of each object may move in the coming step, estimated from the states
// the controller has already seen — never from the scene's paths or the future. This is our
// extension of the paper (whose controller uses the present only): a vertex's speed is the
// larger of its last two displacements over their time, so an object that reversed at a
// waypoint in the middle of the last step (displacement near zero) is still known to be fast.
// At the first instant nothing is known and every speed is 0.
//
// A speed, not a velocity, on purpose: the safety layer assumes the vertex may go in any
// direction at that speed, so a path corner that turns an object towards a camera is covered.
#include <vector>

#include "geometry/ring.h"
#include "kinematics/world.h"

namespace camcov::safety {

class ObservedSpeeds {
 public:
  // Takes the world at its time (later than the last one observed).
  void observe(const kinematics::World& world);

  // Speed bound of vertex v of target i / obstacle i, m/s.
  double target(std::size_t i, std::size_t v) const { return targets_[i][v]; }
  double obstacle(std::size_t i, std::size_t v) const { return obstacles_[i][v]; }
  // The fastest vertex of the object, m/s.
  double fastestTarget(std::size_t i) const { return fastestTargets_[i]; }
  double fastestObstacle(std::size_t i) const { return fastestObstacles_[i]; }

 private:
  struct Kind {
    std::vector<geometry::Ring> previous;       // the rings at the last observation
    std::vector<std::vector<double>> lastStep;  // per vertex: speed over the last step
  };
  static void update(const std::vector<geometry::Ring>& now, double elapsed, Kind& kind,
                     std::vector<std::vector<double>>& speeds, std::vector<double>& fastest);

  bool seen_ = false;
  double lastTime_ = 0.0;
  Kind targetHistory_, obstacleHistory_;
  std::vector<std::vector<double>> targets_, obstacles_;
  std::vector<double> fastestTargets_, fastestObstacles_;
};

}  // namespace camcov::safety
