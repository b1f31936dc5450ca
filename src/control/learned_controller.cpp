#include "control/learned_controller.h"

#include <fmt/format.h>

#include <stdexcept>

#include "control/local_controller.h"
#include "util/input_error.h"

namespace camcov::control {

LearnedController::LearnedController(const scene::Scene& scene, const params::Parameters& params,
                                     const LearnedPolicy& policy)
    : scene_(scene),
      params_(params),
      policy_(policy),
      encoded_(policy.sizes().size()),
      limits_(stepLimits(scene, params.sim.dt)),
      model_(params.reward, scene::lenses(scene)),
      local_(params.local) {
  try {
    requireFits(scene, policy.sizes(), policy.view());
  } catch (const std::invalid_argument& error) {
    throw InputError(fmt::format(
        "method learned: {} (the policy observes at most {} cameras and target rings of {} "
        "vertices; docs/method.md, \"Learned method\")",
        error.what(), policy.sizes().cameras, policy.sizes().vertices));
  }
}

geometry::Pose LearnedController::proposal(const Observation& observation, std::size_t j) {
  encodeObservation(scene_, params_, observation, policy_.sizes(), policy_.view(), j, encoded_);
  const auto [vx, vy, turn] = policy_.act(encoded_);
  const scene::CameraSpec& camera = scene_.cameras[j];
  // Saturated as the simulator saturates it, so the pose is where the command would lead.
  const scene::CameraCommand u = camera.saturate(
      {{vx * camera.maxVelocity, vy * camera.maxVelocity}, turn * camera.maxAngularVelocity});
  return scene::moved(observation.cameras[j], u, params_.sim.dt);
}

void LearnedController::control(const Observation& observation,
                                std::span<scene::CameraCommand> commands) {
  takeInstant(model_, observation);
  team_.assign(observation.cameras.begin(), observation.cameras.end());
  double current = model_.reward(team_);
  // In index order, each camera against the team as the cameras before it left it (as the
  // local optimization's improve()): the policy's step where it does not lower reward(team),
  // eq. (8); else the baseline's local step, which holds the pose if no step raises it.
  for (std::size_t j = 0; j < commands.size(); ++j) {
    const geometry::Pose from = team_[j];
    team_[j] = proposal(observation, j);
    const double proposed = model_.reward(team_);
    if (proposed >= current) {
      current = proposed;
    } else {
      team_[j] = from;
      team_[j] = local_.step(model_, team_, j, current, limits_[j]);
      current = model_.reward(team_);
    }
    commands[j] = commandTowards(from, team_[j], params_.sim.dt);
  }
}

}  // namespace camcov::control
