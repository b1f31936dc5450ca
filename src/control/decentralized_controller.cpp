#include "control/decentralized_controller.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "control/event_kind.h"
#include "control/neighbourhood.h"
#include "control/team_belief.h"
#include "scene/camera_poses_file.h"

namespace camcov::control {

DecentralizedController::DecentralizedController(const scene::Scene& scene,
                                                 const params::Parameters& params,
                                                 std::uint64_t seed)
    : scene_(scene),
      params_(params),
      seed_(seed),
      // The loops' own first global step waits one step to see whether anything moves.
      nextRegroupTime_(params.sim.dt + params.global.T1) {
  const std::vector<geometry::Pose> initial = scene::initialPoses(scene);
  for (std::size_t j = 0; j < scene.cameras.size(); ++j)
    loops_.push_back(makeLoop(j, neighbourhood(initial, j, neighbourhoodSize()), 0.0));
}

DecentralizedController::Loop DecentralizedController::makeLoop(std::size_t j,
                                                                std::vector<std::size_t> members,
                                                                double start) const {
  Loop loop;
  loop.self =
      static_cast<std::size_t>(std::find(members.begin(), members.end(), j) - members.begin());
  if (members.size() < scene_.cameras.size()) {
    loop.scene = std::make_unique<const scene::Scene>(neighbourhoodScene(scene_, members));
  }
  loop.members = std::move(members);
  // One seed for every camera: a team agreed on it before the run, so that cameras that know
  // the same draw the same samples and reach the same plan.
  loop.controller = std::make_unique<PaperController>(
      loop.scene ? *loop.scene : scene_, params_, seed_, PaperController::Variant::Camcov, start);
  return loop;
}

std::optional<geometry::Pose> DecentralizedController::goal(std::size_t camera) const {
  const Loop& loop = loops_[camera];
  return loop.controller->goal(loop.self);
}

void DecentralizedController::takeEvents(std::vector<ControlEvent>& out) {
  for (auto& e : events_)
    out.push_back(std::move(e));
  events_.clear();
}

void DecentralizedController::control(const Observation& observation,
                                      std::span<scene::CameraCommand> commands) {
  // Neighbourhoods are chosen again when the loops' global steps are due (half a step of slack
  // against rounding, as theirs).
  const std::size_t size = neighbourhoodSize();
  const bool regroup =
      size < loops_.size() && observation.time + 0.5 * params_.sim.dt >= nextRegroupTime_;
  if (regroup) nextRegroupTime_ += params_.global.T1;

  std::vector<ControlEvent> loopEvents;
  for (std::size_t j = 0; j < loops_.size(); ++j) {
    const OwnKnowledge* own = observation.own.empty() ? nullptr : &observation.own[j];
    if (own != nullptr && own->world.targets.empty()) {
      // Nothing to cover that it knows of, so nothing its loop could plan for: it turns on
      // the spot, looking round for a target, and plans from the instant it knows one.
      commands[j] = {{0.0, 0.0}, scene_.cameras[j].maxAngularVelocity};
      continue;
    }
    // Full knowledge: every camera's own world is the true one, its teammates' poses known.
    if (own != nullptr) {
      believedTeam(scene_, *own, j, observation.cameras[j], believed_);
    } else {
      believed_.assign(observation.cameras.begin(), observation.cameras.end());
    }
    if (regroup) {
      if (auto members = neighbourhood(believed_, j, size); members != loops_[j].members) {
        events_.push_back({observation.time,
                           std::string(eventName(EventKind::Neighbourhood)),
                           static_cast<int>(j),
                           fmt::format("plans with cameras {}", fmt::join(members, ", ")),
                           {},
                           {}});
        // The old loop goes before the scene it refers to (assignment would replace the scene
        // first).
        loops_[j].controller.reset();
        loops_[j] = makeLoop(j, std::move(members), observation.time);
      }
    }
    Loop& loop = loops_[j];
    planned_.resize(loop.members.size());
    if (own == nullptr && !loop.scene) {
      // The whole team with the true world: the simulator's measurements serve as they are.
      loop.controller->control(observation, planned_);
    } else {
      memberPoses_.clear();
      for (std::size_t i : loop.members)
        memberPoses_.push_back(believed_[i]);
      // Nothing measured for this camera's world or team: its loop sweeps it itself.
      const Observation mine{observation.time, own != nullptr ? own->world : observation.world,
                             memberPoses_};
      loop.controller->control(mine, planned_);
    }
    commands[j] = planned_[loop.self];
    loopEvents.clear();
    loop.controller->takeEvents(loopEvents);
    for (ControlEvent& e : loopEvents) {
      // Its own events, and its team decisions as its own: what it planned for the others is
      // not what they do.
      if (e.camera != -1 && e.camera != static_cast<int>(loop.self)) continue;
      e.camera = static_cast<int>(j);
      events_.push_back(std::move(e));
    }
  }
}

}  // namespace camcov::control
