#pragma once
// The baseline of the paper's evaluation (section VI): local optimization only (section V-E),
// with the same reward, parameters and code as the method.
#include "control/controller.h"
#include "params/parameters.h"
#include "planners/local_optimizer.h"
#include "reward/reward_model.h"
#include "scene/scene.h"

namespace camcov::control {

class LocalController final : public Controller {
 public:
  LocalController(const scene::Scene& scene, const params::Parameters& params);

  void control(const Observation& observation, std::span<scene::CameraCommand> commands) override;
  std::optional<geometry::Pose> goal(std::size_t) const override { return std::nullopt; }
  void takeEvents(std::vector<ControlEvent>&) override {}

 private:
  std::vector<scene::StepLimits> limits_;
  double dt_;
  reward::RewardModel model_;
  planners::LocalOptimizer local_;
  std::vector<geometry::Pose> team_;
};

// The velocity that takes `from` to `to` in one step of dt (yaw the short way round).
scene::CameraCommand commandTowards(const geometry::Pose& from, const geometry::Pose& to,
                                    double dt);
// Per-step limits v_max·dt and γ̇_max·dt of every camera.
std::vector<scene::StepLimits> stepLimits(const scene::Scene& scene, double dt);

}  // namespace camcov::control
