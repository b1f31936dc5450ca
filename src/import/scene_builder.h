#pragma once
// A recording (recording.h) as a self-contained camcov scene: every person a disc
// target with its track, the ball left out or a target or an obstacle, walls as thin
// obstacles and pillars as discs, a boundary around it all, and a camera team. Decisions:
//  - a disc is a regular 12-gon of the given radius about the recorded point;
//  - a track that disappears for longer than maxGap comes back as a new target (its id
//    "7#2"), since nobody knows where the person was; shorter gaps are bridged in a straight
//    line (the scene format's interpolation). Every split is reported;
//  - walls occlude and block cameras but do not stop recorded people: a track that crosses a
//    wall (the recordings are noisy) is kept as recorded and reported;
//  - the busiest window: people present counted every 0.1 s, as the scene will have them
//    (tracks split at gaps, each present from its first sample to its last);
//  - cameras (when not given) are spread evenly along the boundary, 1 m inside it, each
//    facing the boundary's centre; one that would start inside an obstacle moves on along
//    the boundary until it is free.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/vec2.h"
#include "import/recording.h"

namespace camcov::import {

enum class BallAs { None, Target, Obstacle };

// The smallest disc a person or ball may be, m: a disc is written as a 12-gon to the
// millimetre, whose sides (0.52 r) must stay apart at that rounding; a smaller one would be
// written with vertices on top of each other.
inline constexpr double kMinDiscRadius = 0.01;

struct SceneOptions {
  double from = 0.0;  // the window, s from the recording's start
  double to = std::numeric_limits<double>::infinity();
  // > 0: instead of from/to, the window this long with the most people present on average
  // (starts on a 1 s grid, the earliest of equals).
  double busiest = 0.0;
  double personRadius = 0.25;  // m
  double ballRadius = 0.11;    // m (a football)
  BallAs ball = BallAs::None;
  double maxGap = 1.0;         // s
  double margin = 2.0;         // m beyond the tracks and walls (the pitch's run-off)
  double wallThickness = 0.1;  // m
  int cameras = 4;
  std::optional<std::vector<geometry::Pose>> cameraPoses;  // --cameras-from
  double cameraSpeed = 2.0;                                // m/s, v_max
  double cameraTurnRate = 1.0;                             // rad/s, γ̇_max
  double cameraHalfFovDeg = 30.0;                          // θ, degrees
  // The cameras as a real rig has them (docs/scene-format.md, "Resolution", gives the sources):
  // a Full HD image, W = 1920 pixels across the field of view (0: no image model), and the
  // density EN 62676-4 asks to observe what a person does, 62.5 pixels per metre.
  int imageWidth = 1920;
  double minDensity = 62.5;
  // r_j, m; none: the farthest a face-on edge is still resolved, W / 2θ / ρ_min (unlimited
  // without an image model); 0: unlimited.
  std::optional<double> sensingRange;
  // A person's front (their face and chest: who they are and what they do) counts this many
  // times the rest of them, within this half-angle of where they are going
  // (scene::FrontWeighting); 1: no front. Not the ball's.
  double frontWeight = 2.0;
  double frontAngleDeg = 60.0;  // degrees
  std::string description;
};

struct BuiltScene {
  nlohmann::json scene;            // the scene file's content
  std::vector<std::string> notes;  // what was decided about the data, for the user
  int mostAtOnce = 0;              // targets present at once, at most (counted every 0.1 s)
  double duration = 0.0;           // s from the window's start to the last target sample
};

// InputError when nothing is left to make a scene of (no track in the window).
BuiltScene buildScene(const Recording& recording, const SceneOptions& options);

}  // namespace camcov::import
