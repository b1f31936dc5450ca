#pragma once
// Continuous-time collision accounting over one simulation step [t, t + dt]. Samples at the
// steps miss what happens between them (an object at 3 m/s moves 0.3 m in a 0.1 s step), so
// every camera–object and camera–camera distance is followed through the step: cameras move
// linearly between their two poses (the simulator holds a velocity over the step), objects
// move exactly as the scene says (the kinematics at any instant, not interpolated).
// Lipschitz branch and bound (lipschitz_search.h) gives certified results: minimum distances
// within 1e-4 m (also of objects spinning at the scene's limit: where the slope bound runs out
// of samples, every point of an object lies within its reach of its reference point), time closer
// than δ never undercounted and overcounted by at most dt/4096 per crossing of δ. Measurement, not
// control: it may use what the controller may not (the scene's speed bounds, the world between
// samples).
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/kinematics.h"

namespace camcov::safety {

inline constexpr double kDistanceTolerance = 1e-4;  // m, of the minimum distances
inline constexpr int kContactDepth = 12;            // time below δ to dt / 2^12

// The distances at one instant: every camera to every target and obstacle, and the closest
// of them. A step is measured between two of these, and each is taken once per instant.
struct Sample {
  double time = 0.0;
  std::vector<geometry::Vec2> cameras;  // positions
  std::vector<double> objectDistances;  // camera-major: targets, then obstacles, per camera
  double minObjectDistance = std::numeric_limits<double>::infinity();  // m
  double minCameraDistance = std::numeric_limits<double>::infinity();  // m (one camera: ∞)
};

struct StepContacts {
  double minObjectDistance = std::numeric_limits<double>::infinity();  // m, over the step
  double minCameraDistance = std::numeric_limits<double>::infinity();  // m
  double objectContactTime = 0.0;  // s with some camera closer than δ to a target or obstacle
  double cameraContactTime = 0.0;  // s with some pair of cameras closer than δ
  double contactTime = 0.0;        // s with either
  // Per camera: when it first came closer than δ to anything in the step, s after the
  // step's start; negative: never.
  std::vector<double> contactStart;
};

class StepAccounting {
 public:
  StepAccounting(const kinematics::Kinematics& kinematics, double delta);

  // The distances at `world`'s instant for cameras at these poses.
  Sample sample(const kinematics::World& world, std::span<const geometry::Pose> cameras) const;
  // The step between two samples (cameras moving linearly between them, objects as the scene
  // moves them).
  StepContacts measure(const Sample& from, const Sample& to) const;

 private:
  const kinematics::Kinematics& kinematics_;
  double delta_;
  // How the objects move: point speeds are the Lipschitz constants of distances to them,
  // travel and reach bound them where those constants say little (fast spin).
  std::vector<kinematics::MotionBounds> targetBounds_, obstacleBounds_;
};

}  // namespace camcov::safety
