#pragma once
// Section V-B: which camera goes to which goal. The Hungarian method on the estimated travel
// times (CameraSpec::travelTime: obstacles ignored); the team needs the longest of the chosen ones.
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "scene/scene.h"

namespace camcov::control {

struct GoalAssignment {
  std::vector<int> goalOf;  // camera j goes to goals[goalOf[j]]
  double travelTime = 0.0;  // the largest estimated travel time, s
};

// Camera j of `scene` is at cameras[j]; goal g was sampled for camera g's field of view, so
// only a camera of the same θ takes it (in a team of like cameras, any camera takes any goal,
// as in the paper). As many goals as cameras.
GoalAssignment assignGoals(const scene::Scene& scene, std::span<const geometry::Pose> cameras,
                           std::span<const geometry::Pose> goals);

}  // namespace camcov::control
