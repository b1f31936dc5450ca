#pragma once
// Which camera positions and straight motions the planners may use at one instant (paper
// section V-C): inside the boundary and at least d1 from every target and obstacle. Shared by
// Algorithm 2's sampler, the motion planner's validity checkers and the executor, so all
// agree on what "valid" means.
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "kinematics/world.h"

namespace camcov::planners {

class StateValidity {
 public:
  explicit StateValidity(double d1) : d1_(d1) {}

  // Keeps a reference to `world`: it must outlive the next setWorld().
  void setWorld(const kinematics::World& world);
  bool insideBoundary(geometry::Vec2 p) const;
  // At least d1 from every target and obstacle (outside each, and its distance to it ≥ d1).
  bool clearOfObjects(geometry::Vec2 p) const;
  bool isValid(geometry::Vec2 p) const { return insideBoundary(p) && clearOfObjects(p); }
  // The straight motion from a to b: both ends strictly inside the boundary, no boundary edge
  // touched, and every object at least d1 from the segment — or, where one end is already
  // closer (only a camera's current pose can be), no closer than that end, and the other end
  // valid: a camera too close may only move away. Exact, not sampled.
  bool isValidMotion(geometry::Vec2 a, geometry::Vec2 b) const {
    return insideBoundary(a) && insideBoundary(b) && staysClear(a, b);
  }
  // isValidMotion for ends already known to be strictly inside the boundary: no boundary edge
  // touched, and the objects kept at their distance. `endsClear`: both ends are known to be
  // clearOfObjects (a roadmap's milestones), so every object need only be kept d1 from the
  // segment, and the ends' own distances are not measured again.
  bool staysClear(geometry::Vec2 a, geometry::Vec2 b, bool endsClear = false) const;
  double d1() const { return d1_; }

 private:
  double d1_;
  const kinematics::World* world_ = nullptr;
  std::vector<const geometry::Ring*> objects_;
  std::vector<geometry::Box> boxes_;  // of each object, for cheap rejection
  double scale_ = 0.0;                // the largest |coordinate| of the objects' boxes
};

}  // namespace camcov::planners
