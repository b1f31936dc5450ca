#pragma once
// Section V-B: which camera goes to which goal. The Hungarian method on the estimated travel
// times (CameraSpec::travelTime: obstacles ignored); the team needs the longest of the chosen ones.
#include <optional>
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

// camcov-dec (docs/method.md, "Claims"): a teammate's claim, heard in its messages: the goal it
// announced and its bid, the travel time V-B estimates from where it was when it announced it.
struct Claim {
  geometry::Pose goal;
  double bid = 0.0;  // s
};

// Camera j's bid for `goal` beats the claim of camera `claimant` on it: a shorter estimated
// travel time, ties to the lower index (the same answer in every camera's reckoning).
bool outbids(double bid, std::size_t j, const Claim& claim, std::size_t claimant);

// As above, with camera j's claims[j] (none for most; empty: no claims at all): a goal within
// `spot` metres of a claimed one goes to a camera that does not outbid the best claim on it
// (the lowest bid, ties to the lower index) only where no other assignment is possible, so the
// Hungarian method gives the cameras it outbids their next best goals.
GoalAssignment assignGoals(const scene::Scene& scene, std::span<const geometry::Pose> cameras,
                           std::span<const geometry::Pose> goals,
                           std::span<const std::optional<Claim>> claims, double spot);

}  // namespace camcov::control
