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
#include <optional>
#include <vector>

#include "geometry/ring.h"
#include "kinematics/world.h"

namespace camcov::safety {

class ObservedSpeeds {
 public:
  // Takes the world at its time (later than the last one observed).
  void observe(const kinematics::World& world);

  // Speed bound of vertex v of the world's target i / obstacle i, m/s.
  double target(std::size_t i, std::size_t v) const { return targets_.speeds[i][v]; }
  double obstacle(std::size_t i, std::size_t v) const { return obstacles_.speeds[i][v]; }
  // The fastest vertex of the object, m/s.
  double fastestTarget(std::size_t i) const { return targets_.fastest[i]; }
  double fastestObstacle(std::size_t i) const { return obstacles_.fastest[i]; }

 private:
  // Targets, or obstacles. The past is kept per object of the scene (its id: recorded people
  // come and go, so the world's order changes), the answers per ring of the present world.
  struct Kind {
    std::vector<geometry::Ring> previous;       // by id: the ring at the last observation,
                                                // empty if the object was absent
    std::vector<std::vector<double>> lastStep;  // by id: speed over the last step
    std::vector<std::vector<double>> speeds;    // by world ring: the larger of the last two
    std::vector<double> fastest;                // by world ring: the largest of `speeds`
    std::vector<bool> seenNow;                  // by id: in the present world (scratch)
    void update(const std::vector<geometry::Ring>& now, const kinematics::World& world,
                std::uint32_t (*idOf)(const kinematics::World&, std::size_t), double elapsed);
  };

  std::optional<double> lastTime_;  // of the last observation; none yet
  Kind targets_, obstacles_;
};

}  // namespace camcov::safety
