#pragma once
// What our method (docs/method.md, "Our method") learns from watching the world go by: whether
// anything moves, and where things would be if they went on as they last moved. Only instants
// already seen are used (SPEC 3: a controller sees the present, never the scene's future).
#include <optional>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "kinematics/world.h"

namespace camcov::control {

// The world some seconds on, if every target and obstacle kept the velocity its bounding box's
// centre had over the last step seen, without turning or changing shape, each stopped where its
// box would leave the room's box (a forecast that knows no walls but the outer ones).
class Forecast {
 public:
  Forecast(kinematics::World now, std::vector<geometry::Vec2> targetVelocity,
           std::vector<geometry::Vec2> obstacleVelocity, const geometry::Box& room);
  // The world `seconds` (≥ 0) after the last one seen.
  kinematics::World at(double seconds) const;
  // Whether anything would move: a forecast of things standing, turning or deforming in place
  // is the present world.
  bool moves() const;

 private:
  kinematics::World now_;
  std::vector<geometry::Vec2> targetVelocity_, obstacleVelocity_;
  geometry::Box room_;
};

// Per target (obstacle) of `now`, the velocity of its bounding box's centre since `before`,
// matched by scene id; zero for one that was not there before, and all zero unless `now` is
// later than `before`. What the forecast goes on with, and what a camera remembers an object
// moving at (sim/knowledge.h).
std::vector<geometry::Vec2> targetVelocities(const kinematics::World& now,
                                             const kinematics::World& before);
std::vector<geometry::Vec2> obstacleVelocities(const kinematics::World& now,
                                               const kinematics::World& before);

class MotionWatch {
 public:
  // The world at the next instant. Whether a target or obstacle moved, turned, deformed, came or
  // went since the instant before; nullopt until two instants have been seen.
  std::optional<bool> see(const kinematics::World& world);
  // Things going on from the last instant seen as they moved from the one before (standing
  // still until two have been seen; a thing that has just come stands still).
  Forecast forecast(const geometry::Box& room) const;

 private:
  int seen_ = 0;
  kinematics::World before_, last_;
};

}  // namespace camcov::control
