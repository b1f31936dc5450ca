#include "planners/local_optimizer.h"

#include <algorithm>
#include <cmath>

namespace camcov::planners {

LocalOptimizer::Move LocalOptimizer::compassStep(reward::RewardModel& model,
                                                 std::span<geometry::Pose> team, std::size_t j,
                                                 const reward::RewardTerms& current,
                                                 StepLimits limits) const {
  const geometry::Pose here = team[j];
  // The gradient's step is one of the moves tried; it makes the small moves. (Moves by a
  // quarter of the limit as well cost 6 more of the 16 rewards a camera and step, and did not
  // cover more on the tune scenes: docs/method.md.)
  Move best = gradientStep(model, team, j, current.reward, limits).value_or(Move{here, current});
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {1.0, -1.0}) {
      geometry::Pose probe = here;
      probe[axis] += sign * (axis == 2 ? limits.maxRotation : limits.maxTranslation);
      probe.yaw = geometry::wrapAngle(probe.yaw);
      team[j] = probe;
      const auto t = model.terms(team);
      const bool turn = axis == 2;
      const double coverage = reward::coverageTerm(model.params(), t),
                   bestCoverage = reward::coverageTerm(model.params(), best.terms);
      if (t.reward > current.reward &&
          (coverage > bestCoverage ||
           (turn && coverage == bestCoverage && t.reward > best.terms.reward))) {
        best = {probe, t};
      }
    }
  }
  team[j] = here;
  return best;
}

LocalOptimizer::Move LocalOptimizer::bestMove(reward::RewardModel& model,
                                              std::span<geometry::Pose> team, std::size_t j,
                                              const reward::RewardTerms& current,
                                              StepLimits limits) const {
  if (search_ == Search::Compass) return compassStep(model, team, j, current, limits);
  return gradientStep(model, team, j, current.reward, limits).value_or(Move{team[j], current});
}

geometry::Pose LocalOptimizer::step(reward::RewardModel& model, std::span<geometry::Pose> team,
                                    std::size_t j, double currentReward, StepLimits limits) const {
  if (search_ == Search::Compass)
    return compassStep(model, team, j, model.terms(team), limits).pose;
  const auto move = gradientStep(model, team, j, currentReward, limits);
  return move ? move->pose : team[j];
}

std::optional<LocalOptimizer::Move> LocalOptimizer::gradientStep(reward::RewardModel& model,
                                                                 std::span<geometry::Pose> team,
                                                                 std::size_t j,
                                                                 double currentReward,
                                                                 StepLimits limits) const {
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

  const geometry::Pose candidate{current.x + move.x, current.y + move.y,
                                 geometry::wrapAngle(current.yaw + turn)};
  std::optional<Move> better;
  if (std::isfinite(candidate.x) && std::isfinite(candidate.y) && std::isfinite(candidate.yaw)) {
    team[j] = candidate;
    if (const auto t = model.terms(team); t.reward > currentReward) better = Move{candidate, t};
  }
  team[j] = current;
  return better;
}

double LocalOptimizer::improve(reward::RewardModel& model, std::span<geometry::Pose> team,
                               const scene::CameraSet& movable,
                               std::span<const StepLimits> limits) const {
  reward::RewardTerms current = model.terms(team);
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (!movable.contains(j)) continue;
    const Move next = bestMove(model, team, j, current, limits[j]);
    if (next.pose == team[j]) continue;
    team[j] = next.pose;
    current = next.terms;
  }
  return current.reward;
}

}  // namespace camcov::planners
