#include "control/decentralized_controller.h"

#include "control/team_belief.h"

namespace camcov::control {

DecentralizedController::DecentralizedController(const scene::Scene& scene,
                                                 const params::Parameters& params,
                                                 std::uint64_t seed)
    : scene_(scene), planned_(scene.cameras.size()) {
  // One seed for every camera: a team agreed on it before the run, so that cameras that know
  // the same draw the same samples and reach the same plan.
  for (std::size_t j = 0; j < scene.cameras.size(); ++j) {
    loops_.push_back(
        std::make_unique<PaperController>(scene, params, seed, PaperController::Variant::Camcov));
  }
}

std::optional<geometry::Pose> DecentralizedController::goal(std::size_t camera) const {
  return loops_[camera]->goal(camera);
}

void DecentralizedController::takeEvents(std::vector<ControlEvent>& out) {
  for (auto& e : events_)
    out.push_back(std::move(e));
  events_.clear();
}

void DecentralizedController::control(const Observation& observation,
                                      std::span<scene::CameraCommand> commands) {
  std::vector<ControlEvent> loopEvents;
  for (std::size_t j = 0; j < loops_.size(); ++j) {
    if (observation.own.empty()) {
      // Full knowledge: every camera's own world is the true one, its teammates' poses known.
      loops_[j]->control(observation, planned_);
    } else {
      const OwnKnowledge& own = observation.own[j];
      if (own.world.targets.empty()) {
        // Nothing to cover that it knows of, so nothing its loop could plan for: it turns on
        // the spot, looking round for a target, and plans from the instant it knows one.
        commands[j] = {{0.0, 0.0}, scene_.cameras[j].maxAngularVelocity};
        continue;
      }
      believedTeam(scene_, own, j, observation.cameras[j], believed_);
      // Nothing measured for this camera's world: its loop sweeps it itself.
      const Observation mine{observation.time, own.world, believed_};
      loops_[j]->control(mine, planned_);
    }
    commands[j] = planned_[j];
    loopEvents.clear();
    loops_[j]->takeEvents(loopEvents);
    for (ControlEvent& e : loopEvents) {
      // Its own events, and its team decisions as its own: what it planned for the others is
      // not what they do.
      if (e.camera != -1 && e.camera != static_cast<int>(j)) continue;
      e.camera = static_cast<int>(j);
      events_.push_back(std::move(e));
    }
  }
}

}  // namespace camcov::control
