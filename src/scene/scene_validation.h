#pragma once
// Semantic checks behind the loader: what makes a ring, a deformation or a t = 0 placement
// unusable. Each returns an empty description when all is well, so tests can call them alone.
#include <cstddef>
#include <string>
#include <vector>

#include "geometry/ring.h"
#include "scene/scene.h"

namespace camcov::scene {

// Bounds on magnitudes: far beyond any camera scene, and small enough that nothing computed
// from them overflows (areas and orientation tests multiply coordinates; placing an object
// multiplies speeds by times up to 1e9 s) and that a run's work stays bounded (the continuous-
// time distances search a step more finely the faster things move: 1e4 m/s costs a run about
// twice the time of a walking pace).
inline constexpr double kMaxCoordinate = 1e9;  // m, |x| and |y| of every WKT coordinate
inline constexpr double kMaxSpeed = 1e4;       // m/s and rad/s, every velocity, either sign
// Beyond ±1e6 degrees (2,778 turns) a yaw in double precision has lost its fraction of a
// degree: such a number is a mistake, not an angle.
inline constexpr double kMaxYawDegrees = 1e6;
// Importance weights ("edgeWeights", "frontWeight") are relative: at most 1e6 times each other.
inline constexpr double kMaxWeight = 1e6;
// The widest image a camera may have, in pixels, and the finest density a scene may ask for, in
// pixels per metre: far beyond any sensor, and within them every density stays finite.
inline constexpr double kMaxImageWidth = 1e6;
inline constexpr double kMaxMinDensity = 1e9;
// A target's front without "frontAngle": the edges whose outward normal is within 60° of the
// direction of motion — the face and chest of a person, not the flanks, which a camera at the
// side sees only at a grazing angle (docs/scene-format.md, "Importance weights").
inline constexpr double kDefaultFrontAngle = 60.0;

// Zero-length edges, zero area, self-intersections. Empty string for a simple polygon.
std::string describeRingDefect(const geometry::Ring& ring);

// Interpolated shapes between keyframes must stay simple; checked at 15 instants per interval.
std::string describeDeformationDefect(const MovingObject& object);

struct PlacementDefect {
  std::string jsonPath;  // empty when there is no defect
  std::string problem;
};
// At t = 0: cameras inside the boundary (on it is allowed) and not strictly inside an object;
// objects within the boundary (a recorded track: every sample). Every defect of the scene, one
// per camera or object, in the order targets, obstacles, cameras; none for a good scene.
std::vector<PlacementDefect> findPlacementDefects(const Scene& scene);

}  // namespace camcov::scene
