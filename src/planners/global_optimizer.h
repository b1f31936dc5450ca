#pragma once
// Global optimization (paper section V-A, Algorithm 2, "triple sampling"): place the cameras
// one by one, each at the best of K sampled poses that see a point q1 of the target boundary
// not yet covered by the cameras placed before it, scored by reward(C_1, ..., C_j).
#include <optional>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "params/parameters.h"
#include "planners/state_validity.h"
#include "reward/reward_model.h"
#include "util/random.h"

namespace camcov::planners {

struct GlobalResult {
  std::vector<geometry::Pose> poses;  // one per camera, in placement order
  double reward = 0.0;                // reward(T, O, C) of all of them, eq. (8)
};

// nullopt if some camera found no valid pose among its K samples. Uses `model`'s instant.
// `helpers`, models set to the same instant, score the samples on as many more threads; the
// result is the same with any number of them (the samples are drawn first, in order, and the
// first best is taken).
std::optional<GlobalResult> optimizeGlobally(reward::RewardModel& model,
                                             const StateValidity& validity, std::size_t cameras,
                                             int samplesPerCamera, Random& random,
                                             std::span<reward::RewardModel> helpers = {});

}  // namespace camcov::planners
