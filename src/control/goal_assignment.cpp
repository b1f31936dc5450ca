#include "control/goal_assignment.h"

#include <algorithm>
#include <utility>

#include "planners/hungarian.h"

namespace camcov::control {
namespace {

// s: never chosen while the identity is possible
constexpr double kOtherFieldOfView = 1e12;
// s: a spot claimed by a better bidder goes to this camera only where nothing else is possible;
// far below kOtherFieldOfView, far above any travel time.
constexpr double kOutbid = 1e9;

// The best claim on `goal` among `claims` (within `spot` metres): its camera, or none.
std::optional<std::size_t> bestClaimant(const geometry::Pose& goal,
                                        std::span<const std::optional<Claim>> claims, double spot) {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < claims.size(); ++i) {
    if (!claims[i] || geometry::norm(claims[i]->goal.position() - goal.position()) >= spot) {
      continue;
    }
    if (!best || outbids(claims[i]->bid, i, *claims[*best], *best)) best = i;
  }
  return best;
}

}  // namespace

bool outbids(double bid, std::size_t j, const Claim& claim, std::size_t claimant) {
  return std::pair{bid, j} < std::pair{claim.bid, claimant};
}

GoalAssignment assignGoals(const scene::Scene& scene, std::span<const geometry::Pose> cameras,
                           std::span<const geometry::Pose> goals) {
  return assignGoals(scene, cameras, goals, {}, 0.0);
}

GoalAssignment assignGoals(const scene::Scene& scene, std::span<const geometry::Pose> cameras,
                           std::span<const geometry::Pose> goals,
                           std::span<const std::optional<Claim>> claims, double spot) {
  const std::size_t m = goals.size();
  std::vector<double> cost(m * m);
  for (std::size_t j = 0; j < m; ++j) {
    const auto& camera = scene.cameras[j];
    for (std::size_t g = 0; g < m; ++g) {
      cost[j * m + g] = scene.cameras[g].lens != camera.lens
                            ? kOtherFieldOfView
                            : camera.travelTime(cameras[j], goals[g]);
    }
  }
  // What the assignment minimizes: the cost, and a penalty where a better bidder claims the spot.
  std::vector<double> bidCost = cost;
  if (!claims.empty()) {
    for (std::size_t g = 0; g < m; ++g) {
      const auto claimant = bestClaimant(goals[g], claims, spot);
      if (!claimant) continue;
      for (std::size_t j = 0; j < m; ++j) {
        if (j != *claimant && !outbids(cost[j * m + g], j, *claims[*claimant], *claimant)) {
          bidCost[j * m + g] += kOutbid;
        }
      }
    }
  }
  GoalAssignment result;
  result.goalOf = planners::solveAssignment(bidCost, static_cast<int>(m), static_cast<int>(m));
  for (std::size_t j = 0; j < m; ++j)
    result.travelTime = std::max(result.travelTime, cost[j * m + result.goalOf[j]]);
  return result;
}

}  // namespace camcov::control
