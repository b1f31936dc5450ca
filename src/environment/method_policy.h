#pragma once
// A method of the table (control/methods.h) choosing an episode's commands: its controller,
// made from the episode's scene and parameters and the run's seed as a batch makes it, asked
// at each instant in the order sim::simulate asks it. Driven this way, an episode is the
// method's run with that seed, to the bit, so a learned policy is compared with the classical
// ones on the same scenes and seeds.
#include <cstdint>
#include <memory>
#include <span>

#include "control/controller.h"
#include "control/methods.h"
#include "environment/episode.h"

namespace camcov::environment {

class MethodPolicy {
 public:
  MethodPolicy(const control::Method& method, const Episode& episode, std::uint64_t seed);

  // The commands for the episode's present instant (one per camera); the controller's events
  // join the episode's.
  void decide(Episode& episode, std::span<scene::CameraCommand> commands);

 private:
  std::unique_ptr<control::Controller> controller_;
};

}  // namespace camcov::environment
