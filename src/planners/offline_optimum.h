#pragma once
// An offline reference for the best team pose at one instant: what the method's
// reward, eq. (8), can reach in a scene that holds still, found by a search that may take far
// longer than a control step. A reference, not a proof: the search is random and local, and
// says how it found its best and how the best grew with the budget, so a reader can judge
// whether more budget would still help.
//
// Same constraints as the method: every camera valid (StateValidity: inside B and at least
// d1 from every target and obstacle; camera pairs only through the reward's repulsion).
// Rounds until the budget of reward evaluations is spent:
//  1. Algorithm 2 (optimizeGlobally) with K samples per camera: a fresh team;
//  2. block-coordinate ascent on it until a whole pass finds nothing: for each camera in
//     turn, K new samples of Algorithm 2's kind around a point the others leave unseen
//     ("re-placement"), then a pattern search on its x, y and γ with steps halving from 1 m
//     and 0.2 rad down to 1 mm and 0.001 rad ("refinement"); a move is taken only if it
//     raises the team's reward and keeps the camera valid.
// The best team over all rounds is the result.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/vec2.h"
#include "planners/state_validity.h"
#include "reward/reward_model.h"
#include "util/random.h"

namespace camcov::planners {

struct OptimumOptions {
  std::int64_t budget = 200000;  // reward evaluations in all, at least one round's
  int samplesPerCamera = 500;    // K of each round and each re-placement
};

// The best so far, each time it rose.
struct OptimumStep {
  std::int64_t evaluations = 0;
  double reward = 0.0;
  double coverage = 0.0;
};

struct OptimumResult {
  std::vector<geometry::Pose> poses;  // camera j's pose
  reward::RewardTerms terms;          // of the team, eq. (3)-(8)
  int rounds = 0;                     // rounds started
  int foundInRound = 0;               // 1-based
  std::string foundBy;                // "sampling", "re-placement" or "refinement"
  std::int64_t foundAt = 0;           // evaluations spent when it was found
  std::int64_t evaluations = 0;       // spent in all
  std::vector<OptimumStep> curve;
};

// nullopt if no round found a valid pose for every camera. Uses `model`'s instant.
std::optional<OptimumResult> searchOptimum(reward::RewardModel& model,
                                           const StateValidity& validity, std::size_t cameras,
                                           const OptimumOptions& options, Random& random);

}  // namespace camcov::planners
