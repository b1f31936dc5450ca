#include "control/local_controller.h"

namespace camcov::control {

scene::CameraCommand commandTowards(const geometry::Pose& from, const geometry::Pose& to,
                                    double dt) {
  return {(to.position() - from.position()) / dt, geometry::wrapAngle(to.yaw - from.yaw) / dt};
}

std::vector<scene::StepLimits> stepLimits(const scene::Scene& scene, double dt) {
  std::vector<scene::StepLimits> limits;
  for (const auto& c : scene.cameras)
    limits.push_back(c.stepLimits(dt));
  return limits;
}

LocalController::LocalController(const scene::Scene& scene, const params::Parameters& params)
    : limits_(stepLimits(scene, params.sim.dt)),
      dt_(params.sim.dt),
      model_(params.reward, scene::lenses(scene)),
      local_(params.local) {}

void LocalController::control(const Observation& observation,
                              std::span<scene::CameraCommand> commands) {
  takeInstant(model_, observation);
  team_.assign(observation.cameras.begin(), observation.cameras.end());
  local_.improve(model_, team_, scene::CameraSet::firstCameras(team_.size()), limits_);
  for (std::size_t j = 0; j < team_.size(); ++j) {
    commands[j] = commandTowards(observation.cameras[j], team_[j], dt_);
  }
}

}  // namespace camcov::control
