#include "planners/offline_optimum.h"

#include "planners/global_optimizer.h"
#include "planners/team_improvement.h"

namespace camcov::planners {

std::optional<OptimumResult> searchOptimum(reward::RewardModel& model,
                                           const StateValidity& validity, std::size_t cameras,
                                           const OptimumOptions& options, Random& random) {
  TeamImprovement moves(model, validity, options.budget);
  OptimumResult result;
  double bestValue = 0.0;
  const auto offer = [&](const std::vector<geometry::Pose>& team, double value, const char* how) {
    if (!result.poses.empty() && !(value > bestValue)) return;
    bestValue = value;
    result.poses = team;
    result.terms = model.evaluate(team);
    result.foundInRound = result.rounds;
    result.foundBy = how;
    result.foundAt = moves.evaluations();
    result.curve.push_back({moves.evaluations(), value, result.terms.coverage});
  };
  do {
    ++result.rounds;
    const auto start = optimizeGlobally(model, validity, cameras, options.samplesPerCamera, random);
    moves.spend(static_cast<std::int64_t>(cameras) * options.samplesPerCamera);
    if (!start) continue;
    std::vector<geometry::Pose> team = start->poses;
    double value = start->reward;
    offer(team, value, "sampling");
    // Block-coordinate ascent until a whole pass finds nothing.
    for (bool improved = true; improved && !moves.spent();) {
      improved = false;
      for (std::size_t j = 0; j < team.size() && !moves.spent(); ++j) {
        if (moves.replace(team, j, value, options.samplesPerCamera, random)) {
          improved = true;
          offer(team, value, "re-placement");
        }
        if (moves.refine(team, j, value)) {
          improved = true;
          offer(team, value, "refinement");
        }
      }
    }
  } while (!moves.spent());
  result.evaluations = moves.evaluations();
  if (result.poses.empty()) return std::nullopt;
  return result;
}

}  // namespace camcov::planners
