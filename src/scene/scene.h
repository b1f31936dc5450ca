#pragma once
// A scene as loaded from the published benchmark's JSON format (SPEC section 2), already
// normalised: rings open and counter-clockwise, angles in radians, defaults filled in.
// Time-dependent placement lives one layer up, in kinematics/.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/ring.h"
#include "geometry/vec2.h"
#include "scene/camera.h"

namespace camcov::scene {

// Our extension for deforming objects (paper section II: targets "translate, rotate, and/or
// deform"). The local shape is interpolated vertex by vertex, linearly in time, through
// (0, shape), (keyframes[0].time, keyframes[0].shape), ..., (period, shape), then repeats.
struct DeformationKeyframe {
  double time = 0.0;     // seconds into the cycle, strictly inside (0, period)
  geometry::Ring shape;  // same vertex count and correspondence as the object's shape
};

struct Deformation {
  double period = 0.0;                         // seconds, > 0
  std::vector<DeformationKeyframe> keyframes;  // strictly increasing times
};

// Our extension for recorded motion (real people from tracking data): the reference
// point's position at sample times, and optionally the heading. The object is present from
// its first sample to its last and absent before and after (it enters and leaves the scene);
// in between it moves linearly from sample to sample, a gap between two samples included
// (docs/scene-format.md, "Recorded tracks"). Nothing ever looks at a sample later than the present
// except to place the object where it is now.
struct Track {
  std::vector<double> times;              // s, strictly increasing, at least one
  std::vector<geometry::Vec2> positions;  // of the reference point, one per time
  std::vector<double> headings;           // rad, one per time, or empty: the shape unrotated

  double start() const { return times.front(); }
  double end() const { return times.back(); }
  bool presentAt(double t) const { return t >= start() && t <= end(); }
};

// Our extension (the paper's future work, section VII): a target's front, the edges facing
// where it is going, counts `weight` times as much. An edge is in front when its outward normal
// lies within `halfAngle` of the direction of motion, which is estimated from the present and
// the past only (kinematics/edge_importance.h).
struct FrontWeighting {
  double weight = 1.0;     // "frontWeight", >= 0
  double halfAngle = 0.0;  // rad, "frontAngle" in degrees in the file, in (0, 180°]
};

// A target or an obstacle.
struct MovingObject {
  geometry::Ring shape;              // local coordinates about the reference point, CCW
  std::vector<geometry::Vec2> path;  // a closed loop of waypoints of the reference point; one
                                     // point = static (a LINESTRING unfolds: scene/path_forms.h)
                                     // (a tracked object: its first recorded position)
  double velocity = 1.0;             // m/s along the path (closed loop), > 0
  double angularVelocity = 0.0;      // rad/s, counter-clockwise about the reference point
  std::optional<Deformation> deformation;
  std::optional<Track> track;  // recorded motion instead of the path (our extension)
  std::string color;           // "#rrggbb" to draw it in (e.g. a team's), empty: the default
  // Targets only (our extension): how much each metre of edge i of `shape` (vertex i to i + 1
  // of the normalised, counter-clockwise ring) counts in coverage, >= 0; empty: every edge 1.
  std::vector<double> edgeWeights;
  std::optional<FrontWeighting> front;

  bool isWeighted() const { return !edgeWeights.empty() || front.has_value(); }

  bool isStatic() const {
    return path.size() == 1 && angularVelocity == 0.0 && !deformation.has_value() &&
           !track.has_value();
  }
  // Present at t: always, unless its track says otherwise.
  bool presentAt(double t) const { return !track || track->presentAt(t); }
};

// Our extension for football scenes: a pitch from (0, 0) to (length, width), whose markings
// are drawn under everything (scene/pitch_markings.h). Drawing only: nothing collides with it.
struct Pitch {
  double length = 0.0;  // m, along x
  double width = 0.0;   // m, along y
};

// The longest run a scene or a command may ask for, s (sim.duration's range): 100,000 steps at
// the default dt = 0.1 s (sim/run_length.h says why that many).
inline constexpr double kMaxDuration = 1e4;

struct Scene {
  std::string name;         // file stem, e.g. "dynamic9"
  std::string description;  // optional "description" key (our extension), may be empty
  // Optional "family" key (our extension): the family of `camcov generate --family` it was
  // drawn from (scene_families.h), which a bench groups it by; empty for any other scene.
  std::string family;
  geometry::Ring boundary;  // B: time-invariant simple polygon, CCW
  std::vector<MovingObject> targets;
  std::vector<MovingObject> obstacles;
  std::vector<CameraSpec> cameras;
  std::optional<Pitch> pitch;  // "pitch": {"length", "width"} (our extension)
  // "duration" (our extension), s: how long a run of it lasts unless the caller says (an
  // imported recording's window; sim/run_length.h).
  std::optional<double> duration;
  // "resolution" (our extension): what the images must resolve for boundary to count as covered
  // (reward/resolution_coverage.h); then every camera has an image model (Lens::imageWidth), and
  // its records carry resolution coverage beside the plain one.
  std::optional<ResolutionRequirement> resolution;
  // "knowledge" and "comms" (our extension), as a parameter file writes those groups, e.g.
  // {"knowledge": {"limited": true}, "comms": {"range": 10}}: what a camera knows and how the
  // cameras talk in a run of it, where the run's parameters keep their defaults
  // (sim/scene_parameters.h, which also checks them). Null where the scene has neither.
  nlohmann::json knowledgeSettings;
  // What the loader found wrong but allowed ("targets[3]: leaves the boundary: …"), for
  // `camcov validate` to print.
  std::vector<std::string> warnings;

  // Some target's edges are weighted (MovingObject::isWeighted): its records carry weighted
  // coverage beside the plain one.
  bool isWeighted() const;
  // Some object comes and goes (a recorded track): its records carry targetsPresent.
  bool hasPresenceWindows() const;
  // Nothing in it moves, turns, deforms or comes and goes (isStatic): the cameras face one
  // instant for the whole run, whose best team pose `camcov optimum` can search.
  bool holdsStill() const;
};

// Every camera's lens, in camera order: what the visibility and reward stages take.
std::vector<Lens> lenses(const Scene& scene);

// Placement of an object at t = 0: the shape about the first waypoint, unrotated, undeformed.
geometry::Ring initialPolygon(const MovingObject& object);

}  // namespace camcov::scene
