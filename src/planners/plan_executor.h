#pragma once
// Execution of a motion plan (paper section V-D). Each step the camera heads for the next
// intermediate goal — the farthest point of the path it could reach this step at v_max if
// nothing were in the way — pushed by artificial potentials, eq. (11):
//   F = λ4·Fa − λ5·Fr,
// Fa the velocity that reaches the intermediate goal in one step, Fr the sum over targets,
// obstacles and other cameras within d2 of the unit vector towards each, weighted by
// invdist eq. (7) and scaled by v_max so both terms are velocities. The yaw turns towards the
// yaw of the path at the intermediate goal, at most γ̇_max. Without progress along the path
// (SE(2) distance left to the goal) for T3 seconds, the plan is aborted.
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "kinematics/world.h"
#include "params/parameters.h"
#include "scene/camera.h"

namespace camcov::planners {

class PlanExecutor {
 public:
  enum class Status { Idle, Executing, Completed, Aborted };

  // Position and yaw tolerance for "the goal is reached".
  static constexpr double kArrivalDistance = 0.01;  // m
  static constexpr double kArrivalYaw = 0.01;       // rad

  PlanExecutor(const params::PotentialParams& potential, double d2)
      : potential_(potential), d2_(d2) {}

  // Follows `path` (at least one pose, the last is the goal) from time t.
  void start(std::vector<geometry::Pose> path, double t);
  void stop() { status_ = Status::Idle; }
  Status status() const { return status_; }
  bool executing() const { return status_ == Status::Executing; }
  const std::vector<geometry::Pose>& path() const { return path_; }
  const geometry::Pose& goal() const { return path_.back(); }
  // The local optimizer's refinement of the goal (section V-D): the last waypoint moves.
  void refineGoal(const geometry::Pose& goal) { path_.back() = goal; }
  // The point of the path the camera is heading for now.
  const geometry::Pose& intermediateGoal() const { return intermediate_; }
  // The way left from `pose` to the goal, m: to the intermediate goal, then along the path.
  double distanceLeft(const geometry::Pose& pose) const;
  // That way as a path: `pose`, the intermediate goal, the waypoints after it.
  std::vector<geometry::Pose> pathLeft(const geometry::Pose& pose) const;

  // The command for this step; updates the status (Completed, or Aborted after T3).
  scene::CameraCommand step(const geometry::Pose& pose, const kinematics::World& world,
                            std::span<const geometry::Pose> otherCameras, double maxVelocity,
                            double dt, double t);

 private:
  void chooseIntermediateGoal(geometry::Vec2 p, double reach);
  double remaining(const geometry::Pose& pose) const;

  params::PotentialParams potential_;
  double d2_;
  Status status_ = Status::Idle;
  std::vector<geometry::Pose> path_;
  std::vector<double> arcLength_;  // path length up to waypoint i
  double progress_ = 0.0;          // arc length of the current intermediate goal
  geometry::Pose intermediate_;
  double bestRemaining_ = 0.0;
  double lastProgressTime_ = 0.0;
};

// Fr of eq. (11) without its weight: Σ over objects and cameras within d2 of
// invdist · (unit vector from p towards them). Shared with tests.
geometry::Vec2 repulsiveDirection(geometry::Vec2 p, const kinematics::World& world,
                                  std::span<const geometry::Pose> otherCameras, double d2);

}  // namespace camcov::planners
