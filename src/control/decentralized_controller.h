#pragma once
// Our method decentralized (`--method camcov-dec`; docs/method.md, "Decentralized teams"):
// every camera runs our method's loop (PaperController, Variant::Camcov: the global step every
// T1 with its judgement over the horizon, the assignment, the compass local search) on its own
// knowledge only — the world as it saw it or was told (Observation::own), its teammates where
// they last said they were — and follows its own part of the plan it computes. The cameras
// share the run's seed, so where they know the same they compute the same plan: with full
// knowledge (or, once a target is known, messages that reach everyone at every step) each
// camera's part is the one the centralized method gives it, and with full knowledge the team's
// run is camcov's. A camera that knows no target (under limited knowledge) turns on the spot at
// its full rate, looking round for one.
//
// Events: each camera's own (plans, aborts) and its global decisions, with its index.
//
// Holds a reference to `scene`: the scene must outlive the controller.
#include <memory>
#include <vector>

#include "control/controller.h"
#include "control/paper_controller.h"
#include "params/parameters.h"
#include "scene/scene.h"

namespace camcov::control {

class DecentralizedController final : public Controller {
 public:
  DecentralizedController(const scene::Scene& scene, const params::Parameters& params,
                          std::uint64_t seed);

  void control(const Observation& observation, std::span<scene::CameraCommand> commands) override;
  std::optional<geometry::Pose> goal(std::size_t camera) const override;
  void takeEvents(std::vector<ControlEvent>& out) override;

 private:
  const scene::Scene& scene_;
  std::vector<std::unique_ptr<PaperController>> loops_;  // camera j's own loop
  std::vector<geometry::Pose> believed_;                 // scratch: a camera's believedTeam
  std::vector<scene::CameraCommand> planned_;            // scratch: one loop's commands
  std::vector<ControlEvent> events_;
};

}  // namespace camcov::control
