#include "control/goal_assignment.h"

#include <algorithm>

#include "planners/hungarian.h"

namespace camcov::control {

GoalAssignment assignGoals(const scene::Scene& scene, std::span<const geometry::Pose> cameras,
                           std::span<const geometry::Pose> goals) {
  constexpr double kOtherFieldOfView = 1e12;  // s: never chosen while the identity is possible
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
  GoalAssignment result;
  result.goalOf = planners::solveAssignment(cost, static_cast<int>(m), static_cast<int>(m));
  for (std::size_t j = 0; j < m; ++j)
    result.travelTime = std::max(result.travelTime, cost[j * m + result.goalOf[j]]);
  return result;
}

}  // namespace camcov::control
