#pragma once
// The learned method (role example): a learned proposal kept by a reward check. Each camera
// observes what an agent of the learning environments observes (observation_encoding.h, the
// view and padding the policy was trained on); the shared policy's mean action, clipped to
// [-1, 1] and scaled by the camera's own limits as the environments scale normalized actions
// (v_max for vx and vy, γ̇_max for the yaw rate), is its proposal. The camera takes it unless it
// would lower the team's reward (eq. (8)) at the present instant; then it takes the baseline's
// local step instead (section V-E), which holds a pose no small step improves: the policy
// searches where the reward's gradient is flat (a camera that sees nothing), and never drives
// away from a good pose. Deterministic: no random draw. docs/method.md, "Learned method".
#include <vector>

#include "control/controller.h"
#include "control/learned_policy.h"
#include "params/parameters.h"
#include "planners/local_optimizer.h"
#include "reward/reward_model.h"
#include "scene/scene.h"

namespace camcov::control {

class LearnedController final : public Controller {
 public:
  // InputError if the scene has more cameras, obstacles or ring vertices than the policy's
  // observation holds.
  LearnedController(const scene::Scene& scene, const params::Parameters& params,
                    const LearnedPolicy& policy = LearnedPolicy::builtIn());

  void control(const Observation& observation, std::span<scene::CameraCommand> commands) override;
  std::optional<geometry::Pose> goal(std::size_t) const override { return std::nullopt; }
  void takeEvents(std::vector<ControlEvent>&) override {}

 private:
  // Where the policy's mean action, scaled and saturated, takes camera j in one step.
  geometry::Pose proposal(const Observation& observation, std::size_t j);

  const scene::Scene& scene_;
  params::Parameters params_;
  const LearnedPolicy& policy_;
  std::vector<float> encoded_;             // one camera's observation, reused each step
  std::vector<scene::StepLimits> limits_;  // v_max·dt, γ̇_max·dt of every camera
  reward::RewardModel model_;              // reward(team), eq. (8), at the present instant
  planners::LocalOptimizer local_;         // the baseline's step (section V-E)
  std::vector<geometry::Pose> team_;       // the team as the cameras decided so far
};

}  // namespace camcov::control
