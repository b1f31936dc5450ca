#include "planners/local_optimizer.h"

#include <algorithm>
#include <cmath>

namespace camcov::planners {

geometry::Pose LocalOptimizer::compassStep(reward::RewardModel& model,
                                           std::span<geometry::Pose> team, std::size_t j,
                                           double currentReward, StepLimits limits) const {
  const geometry::Pose current = team[j];
  // The gradient's step is one of the moves tried.
  geometry::Pose best = gradientStep(model, team, j, currentReward, limits);
  team[j] = best;
  auto bestTerms = model.terms(team);
  for (const double scale : {1.0, 0.25}) {
    for (int axis = 0; axis < 3; ++axis) {
      for (const double sign : {1.0, -1.0}) {
        geometry::Pose probe = current;
        probe[axis] += sign * scale * (axis == 2 ? limits.maxRotation : limits.maxTranslation);
        probe.yaw = geometry::wrapAngle(probe.yaw);
        team[j] = probe;
        const auto t = model.terms(team);
        const bool turn = axis == 2;
        const double coverage = reward::coverageTerm(model.params(), t),
                     bestCoverage = reward::coverageTerm(model.params(), bestTerms);
        if (t.reward > currentReward &&
            (coverage > bestCoverage ||
             (turn && coverage == bestCoverage && t.reward > bestTerms.reward))) {
          bestTerms = t;
          best = probe;
        }
      }
    }
  }
  team[j] = current;
  return best;
}

geometry::Pose LocalOptimizer::step(reward::RewardModel& model, std::span<geometry::Pose> team,
                                    std::size_t j, double currentReward, StepLimits limits) const {
  return search_ == Search::Compass ? compassStep(model, team, j, currentReward, limits)
                                    : gradientStep(model, team, j, currentReward, limits);
}

geometry::Pose LocalOptimizer::gradientStep(reward::RewardModel& model,
                                            std::span<geometry::Pose> team, std::size_t j,
                                            double currentReward, StepLimits limits) const {
  const geometry::Pose current = team[j];
  const double eps = params_.epsilon;
  // ∂reward/∂x, ∂y, ∂γ by forward differences over ε (the reward has no analytic gradient:
  // visibility is computed, not a formula).
  double gradient[3];
  for (int axis = 0; axis < 3; ++axis) {
    geometry::Pose probe = current;
    probe[axis] += eps;
    team[j] = probe;
    gradient[axis] = (model.reward(team) - currentReward) / eps;
  }
  geometry::Vec2 move{params_.alpha * gradient[0], params_.alpha * gradient[1]};
  double turn = params_.beta * gradient[2];
  // Constraint 3 of Problem 2.2, per time step.
  const double length = geometry::norm(move);
  if (length > limits.maxTranslation) move = move * (limits.maxTranslation / length);
  turn = std::clamp(turn, -limits.maxRotation, limits.maxRotation);

  geometry::Pose candidate{current.x + move.x, current.y + move.y,
                           geometry::wrapAngle(current.yaw + turn)};
  team[j] = candidate;
  const bool better = std::isfinite(candidate.x) && std::isfinite(candidate.y) &&
                      std::isfinite(candidate.yaw) && model.reward(team) > currentReward;
  team[j] = current;
  return better ? candidate : current;
}

double LocalOptimizer::improve(reward::RewardModel& model, std::span<geometry::Pose> team,
                               const scene::CameraSet& movable,
                               std::span<const StepLimits> limits) const {
  double current = model.reward(team);
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (!movable.contains(j)) continue;
    const geometry::Pose next = step(model, team, j, current, limits[j]);
    if (next == team[j]) continue;
    team[j] = next;
    current = model.reward(team);
  }
  return current;
}

}  // namespace camcov::planners
