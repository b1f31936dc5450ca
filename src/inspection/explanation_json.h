#pragma once
// What the visibility playground draws at one instant, as the engine (src/wasm) answers its
// `explain`: the terms and S as `camcov inspect` computes them, and what inspect does not say —
// each camera's field of view and terms alone, why a camera misses a segment, one sweep event
// by event.
#include <span>

#include <nlohmann/json.hpp>

#include "geometry/vec2.h"
#include "kinematics/kinematics.h"
#include "reward/reward_model.h"
#include "scene/scene.h"

namespace camcov::inspection {

// Which of the costly parts to add: the reasons for segment `reasonsFor` of S (O(n) a camera,
// so for the segment asked about only) and camera `traceCamera`'s sweep; -1 (or out of range):
// left out.
struct ExplanationAsks {
  int traceCamera = -1;
  int reasonsFor = -1;
};

// t and the team's terms; the boundary, each target and obstacle (its scene index, ring, and
// where its shape's frame is); each camera's pose, half field of view, view polygon, visible
// length and terms alone (reward::termsAlone); S by columns (target, edge, the ends ax ay bx by
// in a row, visibleBy: a large target's thousands of segments as objects cost a drag most of its
// time); then what `asks` asks for. `model` holds the world of `kinematics` at `time`.
nlohmann::json explanationJson(const scene::Scene& scene, const kinematics::Kinematics& kinematics,
                               double time, std::span<const geometry::Pose> cameras,
                               reward::RewardModel& model, const ExplanationAsks& asks);

}  // namespace camcov::inspection
