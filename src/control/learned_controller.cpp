#include "control/learned_controller.h"

#include <fmt/format.h>

#include <stdexcept>

#include "util/input_error.h"

namespace camcov::control {

LearnedController::LearnedController(const scene::Scene& scene, const params::Parameters& params,
                                     const LearnedPolicy& policy)
    : scene_(scene), params_(params), policy_(policy), encoded_(policy.sizes().size()) {
  try {
    requireFits(scene, policy.sizes(), policy.view());
  } catch (const std::invalid_argument& error) {
    throw InputError(fmt::format(
        "method learned: {} (the policy observes at most {} cameras and target rings of {} "
        "vertices; docs/method.md, \"Learned method\")",
        error.what(), policy.sizes().cameras, policy.sizes().vertices));
  }
}

void LearnedController::control(const Observation& observation,
                                std::span<scene::CameraCommand> commands) {
  for (std::size_t j = 0; j < commands.size(); ++j) {
    encodeObservation(scene_, params_, observation, policy_.sizes(), policy_.view(), j, encoded_);
    const auto [vx, vy, turn] = policy_.act(encoded_);
    const scene::CameraSpec& camera = scene_.cameras[j];
    commands[j] = {{vx * camera.maxVelocity, vy * camera.maxVelocity},
                   turn * camera.maxAngularVelocity};
  }
}

}  // namespace camcov::control
