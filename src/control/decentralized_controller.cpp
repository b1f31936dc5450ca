#include "control/decentralized_controller.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "control/event_kind.h"
#include "control/neighbourhood.h"
#include "control/team_belief.h"
#include "kinematics/world_region.h"
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
  for (std::size_t j = 0; j < scene.cameras.size(); ++j) {
    // With heardOnly, before any message a camera knows of no teammate to plan with.
    loops_.push_back(makeLoop(j,
                              heardOnly() ? neighbourhood(initial, j, neighbourhoodSize(), {})
                                          : neighbourhood(initial, j, neighbourhoodSize()),
                              0.0));
  }
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
  if (ownPartOnly()) loop.controller->moveOwnCameraOnly(loop.self);
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

void DecentralizedController::heardClaims(const OwnKnowledge& own, std::size_t j, double time) {
  claims_.assign(scene_.cameras.size(), std::nullopt);
  for (std::size_t i = 0; i < own.teammates.size(); ++i) {
    const auto& heard = own.teammates[i];
    if (i == j || !heard || !heard->goal || time - heard->sentAt > params_.camcov.claims) continue;
    claims_[i] = Claim{*heard->goal, scene_.cameras[i].travelTime(heard->pose, *heard->goal)};
  }
}

void DecentralizedController::yieldIfOutbid(std::size_t j, const geometry::Pose& pose,
                                            double time) {
  Loop& loop = loops_[j];
  const auto goal = loop.controller->goal(loop.self);
  if (!goal) return;
  const Claim mine{*goal, scene_.cameras[j].travelTime(pose, *goal)};
  for (std::size_t i = 0; i < claims_.size(); ++i) {
    if (!claims_[i] ||
        geometry::norm(claims_[i]->goal.position() - goal->position()) >= params_.reward.d2 ||
        !outbids(claims_[i]->bid, i, mine, j)) {
      continue;
    }
    events_.push_back({time,
                       std::string(eventName(EventKind::Outbid)),
                       static_cast<int>(j),
                       fmt::format("camera {} claims its goal, {:.1f} s away against {:.1f} s", i,
                                   claims_[i]->bid, mine.bid),
                       {},
                       {}});
    loop.controller->giveUp(loop.self);
    return;
  }
}

const kinematics::World& DecentralizedController::plannedIn(const kinematics::World& known,
                                                            const Loop& loop) {
  const double widen = params_.camcov.region;
  if (!loop.scene || !std::isfinite(widen)) return known;
  std::vector<geometry::Vec2> positions;
  for (const geometry::Pose& p : memberPoses_)
    positions.push_back(p.position());
  const geometry::Box members = geometry::boundingBox(positions);
  const double side = std::max(members.max.x - members.min.x, members.max.y - members.min.y);
  region_ = kinematics::worldInRegion(known, geometry::grown(members, widen * side),
                                      positions[loop.self]);
  return region_ && !region_->targets.empty() ? *region_ : known;
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
    // With heardOnly, the teammates it has heard of; it chooses again when it hears of one more.
    scene::CameraSet heard;
    std::size_t heardCount = 0;
    if (heardOnly()) {
      for (std::size_t i = 0; i < own->teammates.size(); ++i) {
        if (i != j && own->teammates[i]) {
          heard.insert(i);
          ++heardCount;
        }
      }
    }
    if (regroup || heardCount != loops_[j].heard) {
      auto members = heardOnly() ? neighbourhood(believed_, j, size, heard)
                                 : neighbourhood(believed_, j, size);
      if (members != loops_[j].members) {
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
      loops_[j].heard = heardCount;
    }
    Loop& loop = loops_[j];
    if (own != nullptr && params_.camcov.claims > 0.0) {
      heardClaims(*own, j, observation.time);
      memberClaims_.clear();
      for (std::size_t i : loop.members)
        memberClaims_.push_back(claims_[i]);
      loop.controller->setClaims(memberClaims_);
      yieldIfOutbid(j, observation.cameras[j], observation.time);
    }
    planned_.resize(loop.members.size());
    if (own == nullptr && !loop.scene) {
      // The whole team with the true world: the simulator's measurements serve as they are.
      loop.controller->control(observation, planned_);
    } else {
      memberPoses_.clear();
      for (std::size_t i : loop.members)
        memberPoses_.push_back(believed_[i]);
      // Nothing measured for this camera's world or team: its loop sweeps it itself.
      const Observation mine{observation.time,
                             plannedIn(own != nullptr ? own->world : observation.world, loop),
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
