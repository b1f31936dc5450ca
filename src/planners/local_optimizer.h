#pragma once
// Local optimization (paper section V-E): gradient ascent on the reward for one camera's pose,
// with a forward-difference gradient over ε, steps α (translation) and β (rotation),
// saturated to what the camera can do in one time step, taken only if the reward rises.
#include <cstdint>
#include <optional>
#include <span>

#include "geometry/vec2.h"
#include "params/parameters.h"
#include "reward/reward_model.h"
#include "scene/camera.h"

namespace camcov::planners {

// How far one step may go: the camera's own limits (scene/camera.h).
using scene::StepLimits;

class LocalOptimizer {
 public:
  // How a step is found: the paper's gradient ascent, or our compass search: the
  // best of the gradient's step and moves by the step's limit along ±x, ±y and ±γ.
  enum class Search { Gradient, Compass };

  explicit LocalOptimizer(const params::LocalParams& params, Search search = Search::Gradient)
      : params_(params), search_(search) {}

  // The pose camera j of `team` should move to in one step (its current pose if no step
  // along the gradient raises reward(team)). `team` is restored before returning.
  // `currentReward` is reward(team) as given (the caller usually has it).
  geometry::Pose step(reward::RewardModel& model, std::span<geometry::Pose> team, std::size_t j,
                      double currentReward, StepLimits limits) const;

  // One step for each camera j in `movable`, in index order, each against
  // the team as the cameras before it left it (so moves never conflict). Updates `team`;
  // returns its reward.
  double improve(reward::RewardModel& model, std::span<geometry::Pose> team,
                 const scene::CameraSet& movable, std::span<const StepLimits> limits) const;

 private:
  // A step for camera j, and the terms of the team with camera j there, which the search has
  // worked out anyway (improve() takes them as the team's next, rather than evaluate again).
  struct Move {
    geometry::Pose pose;
    reward::RewardTerms terms;
  };
  // The gradient's step if it raises the reward above `currentReward`.
  std::optional<Move> gradientStep(reward::RewardModel& model, std::span<geometry::Pose> team,
                                   std::size_t j, double currentReward, StepLimits limits) const;
  // `current`: the terms of `team` as given.
  Move compassStep(reward::RewardModel& model, std::span<geometry::Pose> team, std::size_t j,
                   const reward::RewardTerms& current, StepLimits limits) const;
  Move bestMove(reward::RewardModel& model, std::span<geometry::Pose> team, std::size_t j,
                const reward::RewardTerms& current, StepLimits limits) const;

  params::LocalParams params_;
  Search search_;
};

}  // namespace camcov::planners
