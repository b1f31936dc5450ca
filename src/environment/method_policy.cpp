#include "environment/method_policy.h"

namespace camcov::environment {

MethodPolicy::MethodPolicy(const control::Method& method, const Episode& episode,
                           std::uint64_t seed)
    : controller_(method.make(episode.scene(), episode.params(), seed)) {}

void MethodPolicy::decide(Episode& episode, std::span<scene::CameraCommand> commands) {
  controller_->control(episode.observation(), commands);
  controller_->takeEvents(episode.events());
}

}  // namespace camcov::environment
