#include "environment/method_policy.h"

namespace camcov::environment {

MethodPolicy::MethodPolicy(const control::Method& method, const Episode& episode,
                           std::uint64_t seed)
    : controller_(method.make(episode.scene(), episode.params(), seed)),
      goals_(episode.scene().cameras.size()) {}

void MethodPolicy::decide(Episode& episode, std::span<scene::CameraCommand> commands) {
  controller_->control(episode.observation(), commands);
  controller_->takeEvents(episode.events());
  for (std::size_t j = 0; j < goals_.size(); ++j)
    goals_[j] = controller_->goal(j);
}

}  // namespace camcov::environment
