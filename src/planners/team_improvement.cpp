#include "planners/team_improvement.h"

namespace camcov::planners {

bool TeamImprovement::replace(std::vector<geometry::Pose>& team, std::size_t j, double& value,
                              int samples, Random& random) {
  std::vector<geometry::Pose> others = team;
  others.erase(others.begin() + static_cast<std::ptrdiff_t>(j));
  model_.evaluate(others);
  if (!sampler_.focusOnUnseen(model_, random)) return false;
  const geometry::Pose kept = team[j];
  geometry::Pose best = kept;
  for (int k = 0; k < samples && !spent(); ++k) {
    const auto pose = sampler_.sample(random, validity_, model_.lens(j));
    if (!pose) continue;
    team[j] = *pose;
    const double r = reward(team);
    if (r > value) {
      value = r;
      best = *pose;
    }
  }
  team[j] = best;
  return !(best == kept);
}

bool TeamImprovement::refine(std::vector<geometry::Pose>& team, std::size_t j, double& value) {
  bool moved = false;
  double step = 1.0, turn = 0.2;
  while (step >= 1e-3 && !spent()) {
    bool better = false;
    for (int axis = 0; axis < 3 && !spent(); ++axis) {
      for (const double sign : {1.0, -1.0}) {
        const geometry::Pose kept = team[j];
        geometry::Pose probe = kept;
        probe[axis] += sign * (axis == 2 ? turn : step);
        probe.yaw = geometry::wrapAngle(probe.yaw);
        if (!validity_.isValid(probe.position())) continue;
        team[j] = probe;
        const double r = reward(team);
        if (r > value) {
          value = r;
          better = moved = true;
          break;
        }
        team[j] = kept;
      }
    }
    if (!better) {
      step *= 0.5;
      turn *= 0.5;
    }
  }
  return moved;
}

bool TeamImprovement::refineAll(std::vector<geometry::Pose>& team, double& value,
                                const scene::CameraSet& movable) {
  bool moved = false;
  for (bool pass = true; pass && !spent();) {
    pass = false;
    for (std::size_t j = 0; j < team.size() && !spent(); ++j) {
      if (movable.contains(j)) pass = refine(team, j, value) || pass;
    }
    moved = moved || pass;
  }
  return moved;
}

}  // namespace camcov::planners
