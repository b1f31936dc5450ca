#pragma once
// `camcov inspect --json`: one instant as the reward sees it, written once for the two front
// ends that print it, the CLI and the WebAssembly engine (src/wasm).
#include <cstdint>
#include <span>

#include <nlohmann/json.hpp>

#include "geometry/vec2.h"
#include "reward/reward_model.h"
#include "scene/scene.h"

namespace camcov::inspection {

// The cameras of a segment's visibleBy, by number, lowest first.
nlohmann::json cameraNumbers(const scene::CameraSet& visibleBy);

// The reward's terms (eq. (3), (5), (6), (8)); weightedCoverage too where the scene is weighted.
nlohmann::json termsJson(const reward::RewardTerms& terms, bool weighted);

// The scene's name, t, the team's terms and the targets' perimeter, each camera's pose and the
// length it sees, and S: each segment's ends, target, edge, length, visibleBy and, where
// weighted, its edge's importance. `model` holds the world at `time` and has just evaluated
// `cameras` into `terms`.
nlohmann::json inspectionJson(const scene::Scene& scene, double time,
                              std::span<const geometry::Pose> cameras,
                              const reward::RewardModel& model, const reward::RewardTerms& terms);

}  // namespace camcov::inspection
