#pragma once
// The learned method (role example): each camera observes what an agent of the learning
// environments observes (observation_encoding.h, the view and padding the policy was trained
// on) and moves by the shared policy's mean action, clipped to [-1, 1] and scaled by its own
// limits as the environments scale normalized actions (v_max for vx and vy, γ̇_max for the yaw
// rate). Deterministic: no random draw. docs/method.md, "Learned method".
#include <vector>

#include "control/controller.h"
#include "control/learned_policy.h"
#include "params/parameters.h"
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
  const scene::Scene& scene_;
  params::Parameters params_;
  const LearnedPolicy& policy_;
  std::vector<float> encoded_;  // one camera's observation, reused each step
};

}  // namespace camcov::control
