#pragma once
// Semantic checks behind the loader: what makes a ring, a deformation or a t = 0 placement
// unusable. Each returns an empty description when all is well, so tests can call them alone.
#include <cstddef>
#include <string>

#include "geometry/ring.h"
#include "scene/scene.h"

namespace camcov::scene {

// The visibility sweep keeps visibleBy(s_l) as a 64-bit mask.
inline constexpr std::size_t kMaxCameras = 64;

// Zero-length edges, zero area, self-intersections. Empty string for a simple polygon.
std::string describeRingDefect(const geometry::Ring& ring);

// Interpolated shapes between keyframes must stay simple; checked at 15 instants per interval.
std::string describeDeformationDefect(const MovingObject& object);

struct PlacementDefect {
  std::string jsonPath;  // empty when there is no defect
  std::string problem;
};
// At t = 0: cameras inside the boundary (on it is allowed) and not strictly inside an object;
// objects within the boundary.
PlacementDefect findPlacementDefect(const Scene& scene);

}  // namespace camcov::scene
