#pragma once
// What one frame shows, as plain data: the world at one instant, the targets' boundaries as
// the sweep's segments S with visibleBy (paper section IV-B), each camera's pose, view, plan
// and goal, the objects' paths, and the caption's numbers. FrameBuilder fills the part that
// follows from a scene, a time and camera poses; whoever knows more (a recorded run) adds
// plans and goals. FrameRenderer draws it.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "kinematics/kinematics.h"
#include "kinematics/world.h"
#include "scene/scene.h"
#include "visibility/occluders.h"
#include "visibility/segment.h"
#include "visibility/sweep.h"
#include "viz/palette.h"

namespace camcov::viz {

struct CameraView {
  geometry::Pose pose;
  geometry::Ring view;                 // its field of view clipped to what it can see
  std::optional<geometry::Pose> goal;  // where its plan leads, if it follows one
  std::vector<geometry::Vec2> plan;    // the rest of its planned path, from the camera on
};

// The closed loop an object's reference point travels (SPEC section 2), for objects that move
// or turn.
struct ObjectPath {
  std::vector<geometry::Vec2> waypoints;  // one point: the object turns in place
  double velocity = 0.0;                  // m/s along the loop
  double angularVelocity = 0.0;           // rad/s, counter-clockwise

  bool operator==(const ObjectPath&) const = default;
  // "1.5 m/s, 0.2 rad/s": what the frames write beside the path and the explorer shows.
  std::string speedLabel() const;
};

struct Caption {
  std::string title;      // the scene's name
  std::string subtitle;   // what the cameras are doing, e.g. "method paper, seed 1"
  double time = 0.0;      // s
  double coverage = 0.0;  // eq. (3), in [0, 1]
  // Importance-weighted coverage (reward::RewardTerms), for a weighted scene's frames only.
  std::optional<double> weightedCoverage;
  // Resolution-aware coverage (reward/resolution_coverage.h), for the frames of a scene that
  // asks a resolution only.
  std::optional<double> resolutionCoverage;
  double utilization = 0.0;  // eq. (5), in [0, 1]
};

struct Frame {
  Caption caption;
  kinematics::World world;
  // Per target of `world`: its own colour (a recorded player's team), or none: the palette's.
  std::vector<std::optional<Rgb>> targetColours;
  std::vector<visibility::Segment> segments;  // every target's boundary, seen or not
  // The pieces of seen boundary no camera resolves (a scene that asks a resolution only):
  // drawn over the seen in another colour.
  std::vector<visibility::Segment> unresolved;
  std::vector<CameraView> cameras;
  std::vector<ObjectPath> paths;
  std::vector<std::vector<geometry::Vec2>> markings;  // a football pitch's (scene::Pitch)
};

// Computes frames of one scene. Keeps the sweep's buffers between calls, so stepping through a
// run allocates little; one builder per thread.
class FrameBuilder {
 public:
  explicit FrameBuilder(const scene::Scene& scene);

  // The world at `time`, visibility from `cameras` (at most Sweep::kMaxCameras), coverage and
  // utilization, the caption's title and time. Plans, goals and the subtitle are left empty.
  // Reuses the buffers of `out`. Camera j is the scene's camera j.
  void build(double time, std::span<const geometry::Pose> cameras, Frame& out);

 private:
  kinematics::Kinematics kinematics_;
  std::string sceneName_;
  bool weighted_ = false;                    // its caption has weighted coverage
  std::vector<scene::Lens> lenses_;          // of camera j
  std::vector<std::optional<Rgb>> colours_;  // of each scene target
  std::vector<ObjectPath> paths_;
  std::vector<std::vector<geometry::Vec2>> markings_;
  visibility::Occluders occluders_;
  visibility::Sweep sweep_;
};

}  // namespace camcov::viz
