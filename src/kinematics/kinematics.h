#pragma once
// Placement of every object at any time t (SPEC section 2): translation along the closed
// path, rotation by angularVelocity·t about the reference point, and the deformation
// extension. The controller asks only for the present; nothing here looks ahead on its own.
#include <vector>

#include <optional>

#include "kinematics/path_motion.h"
#include "kinematics/track_motion.h"
#include "kinematics/world.h"
#include "scene/scene.h"

namespace camcov::kinematics {

struct ObjectPose {
  geometry::Vec2 reference;  // reference point in world coordinates
  double angle = 0.0;        // rotation of the shape, radians (ω·t, not wrapped)
};

// How an object can move, over all time, in the parts the safety layer's distance bounds use.
// Not something a controller may know.
struct MotionBounds {
  double travel = 0.0;       // m/s: its reference point never moves faster
  double reach = 0.0;        // m: no point of it is ever farther from its reference point
  double turnRate = 0.0;     // rad/s: |ω|, or a recorded track's fastest turn
  double deformation = 0.0;  // m/s: the fastest vertex of its deformation, in its own frame
  // No point of the object ever moves faster than this, m/s: a Lipschitz constant for
  // distances to the object.
  double pointSpeed() const { return travel + turnRate * reach + deformation; }
};

class Kinematics {
 public:
  explicit Kinematics(const scene::Scene& scene);

  // Fills `out` (reusing its buffers, so a caller stepping through time allocates nothing)
  // with the objects present at t and their scene indices.
  void worldAt(double t, World& out) const;
  World worldAt(double t) const;

  ObjectPose targetPose(std::size_t i, double t) const;
  ObjectPose obstaclePose(std::size_t i, double t) const;
  // One object at time t into `out` (as worldAt places it), for callers that look between
  // two instants of the world (the safety layer's continuous-time accounting).
  void placeTarget(std::size_t i, double t, geometry::Ring& out) const;
  void placeObstacle(std::size_t i, double t, geometry::Ring& out) const;
  // Path speed, the largest radius of any shape it takes, |ω| and the fastest vertex of its
  // deformation: the bounds of every motion the object may make.
  MotionBounds targetMotionBounds(std::size_t i) const;
  MotionBounds obstacleMotionBounds(std::size_t i) const;
  bool targetPresent(std::size_t i, double t) const { return scene_.targets.at(i).presentAt(t); }
  bool obstaclePresent(std::size_t i, double t) const {
    return scene_.obstacles.at(i).presentAt(t);
  }
  const scene::Scene& scene() const { return scene_; }

 private:
  // How one object moves: along its loop, or as recorded.
  struct Motion {
    PathMotion path;
    std::optional<TrackMotion> track;
  };
  static Motion motionOf(const scene::MovingObject& object);
  static ObjectPose pose(const scene::MovingObject& object, const Motion& motion, double t);
  static MotionBounds motionBounds(const scene::MovingObject& object, const Motion& motion);
  static void place(const scene::MovingObject& object, const Motion& motion, double t,
                    geometry::Ring& out);

  // The direction of motion of target i at t (edge_importance.h), if it has a front.
  std::optional<geometry::Vec2> targetMotion(std::size_t i, double t) const;

  scene::Scene scene_;  // a copy: small, and a Kinematics must not outlive what it describes
  std::vector<Motion> targetMotion_;
  std::vector<Motion> obstacleMotion_;
  bool weighted_ = false;  // scene_.isWeighted()
};

}  // namespace camcov::kinematics
