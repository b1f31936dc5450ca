#include "control/decentralized_controller.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "control/event_kind.h"
#include "control/neighbourhood.h"
#include "control/team_belief.h"
#include "kinematics/world_region.h"
#include "scene/camera_poses_file.h"
#include "util/run_threads.h"
#include "util/worker_pool.h"

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
  loops_.resize(scene.cameras.size());
  for (std::size_t j = 0; j < scene.cameras.size(); ++j) {
    // With heardOnly, before any message a camera knows of no teammate to plan with.
    startLoop(j,
              heardOnly() ? neighbourhood(initial, j, neighbourhoodSize(), {})
                          : neighbourhood(initial, j, neighbourhoodSize()),
              0.0);
  }
}

void DecentralizedController::startLoop(std::size_t j, std::vector<std::size_t> members,
                                        double start) {
  Loop& loop = loops_[j];
  // The old controller goes before the scene it refers to.
  loop.controller.reset();
  loop.scene.reset();
  loop.self =
      static_cast<std::size_t>(std::find(members.begin(), members.end(), j) - members.begin());
  if (members.size() < scene_.cameras.size()) {
    loop.scene = std::make_unique<const scene::Scene>(neighbourhoodScene(scene_, members));
  }
  loop.members = std::move(members);
  // One seed for every camera: a team agreed on it before the run, so that cameras that know
  // the same draw the same samples and reach the same plan. The run's threads go to the loops
  // first (control()), to each loop's own global step what is left over.
  const unsigned threads = std::max<unsigned>(
      1, runThreads() / static_cast<unsigned>(std::max<std::size_t>(1, scene_.cameras.size())));
  loop.controller =
      std::make_unique<PaperController>(loop.scene ? *loop.scene : scene_, params_, seed_,
                                        PaperController::Variant::Camcov, start, threads);
  if (ownPartOnly()) loop.controller->moveOwnCameraOnly(loop.self);
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
  auto& claims = loops_[j].claims;
  claims.assign(scene_.cameras.size(), std::nullopt);
  for (std::size_t i = 0; i < own.teammates.size(); ++i) {
    const auto& heard = own.teammates[i];
    if (i == j || !heard || !heard->goal || time - heard->sentAt > params_.camcov.claims) continue;
    claims[i] = Claim{*heard->goal, scene_.cameras[i].travelTime(heard->pose, *heard->goal)};
  }
}

void DecentralizedController::yieldIfOutbid(std::size_t j, const geometry::Pose& pose,
                                            double time) {
  Loop& loop = loops_[j];
  const auto goal = loop.controller->goal(loop.self);
  if (!goal) return;
  const Claim mine{*goal, scene_.cameras[j].travelTime(pose, *goal)};
  for (std::size_t i = 0; i < loop.claims.size(); ++i) {
    const auto& claim = loop.claims[i];
    if (!claim || geometry::norm(claim->goal.position() - goal->position()) >= params_.reward.d2 ||
        !outbids(claim->bid, i, mine, j)) {
      continue;
    }
    loop.events.push_back({time,
                           std::string(eventName(EventKind::Outbid)),
                           static_cast<int>(j),
                           fmt::format("camera {} claims its goal, {:.1f} s away against {:.1f} s",
                                       i, claim->bid, mine.bid),
                           {},
                           {}});
    loop.controller->giveUp(loop.self);
    return;
  }
}

const kinematics::World& DecentralizedController::plannedIn(const kinematics::World& known,
                                                            Loop& loop) const {
  const double widen = params_.camcov.region;
  if (!loop.scene || !std::isfinite(widen)) return known;
  std::vector<geometry::Vec2> positions;
  for (const geometry::Pose& p : loop.memberPoses)
    positions.push_back(p.position());
  const geometry::Box members = geometry::boundingBox(positions);
  const double side = std::max(members.max.x - members.min.x, members.max.y - members.min.y);
  loop.region = kinematics::worldInRegion(known, geometry::grown(members, widen * side),
                                          positions[loop.self]);
  return loop.region && !loop.region->targets.empty() ? *loop.region : known;
}

void DecentralizedController::control(const Observation& observation,
                                      std::span<scene::CameraCommand> commands) {
  // Neighbourhoods are chosen again when the loops' global steps are due (half a step of slack
  // against rounding, as theirs).
  const bool regroup =
      inNeighbourhoods() && observation.time + 0.5 * params_.sim.dt >= nextRegroupTime_;
  if (regroup) nextRegroupTime_ += params_.global.T1;

  // A loop that throws fails the step as it would alone: the first camera's error, after every
  // thread is done.
  std::vector<std::exception_ptr> errors(loops_.size());
  forEachOnWorkers(loops_.size(), runThreads(), [&](std::size_t j) {
    try {
      controlCamera(observation, j, regroup, commands[j]);
    } catch (...) {
      errors[j] = std::current_exception();
    }
  });
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  for (Loop& loop : loops_) {
    for (ControlEvent& e : loop.events)
      events_.push_back(std::move(e));
    loop.events.clear();
  }
}

void DecentralizedController::controlCamera(const Observation& observation, std::size_t j,
                                            bool regroup, scene::CameraCommand& command) {
  const OwnKnowledge* own = observation.own.empty() ? nullptr : &observation.own[j];
  if (own != nullptr && own->world.targets.empty()) {
    // Nothing to cover that it knows of, so nothing its loop could plan for: it turns on
    // the spot, looking round for a target, and plans from the instant it knows one.
    command = {{0.0, 0.0}, scene_.cameras[j].maxAngularVelocity};
    return;
  }
  // Full knowledge: every camera's own world is the true one, its teammates' poses known.
  std::vector<geometry::Pose>& believed = loops_[j].believed;
  if (own != nullptr) {
    believedTeam(scene_, *own, j, observation.cameras[j], believed);
  } else {
    believed.assign(observation.cameras.begin(), observation.cameras.end());
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
    const std::size_t size = neighbourhoodSize();
    auto members =
        heardOnly() ? neighbourhood(believed, j, size, heard) : neighbourhood(believed, j, size);
    if (members != loops_[j].members) {
      ControlEvent chosen{observation.time,
                          std::string(eventName(EventKind::Neighbourhood)),
                          static_cast<int>(j),
                          fmt::format("plans with cameras {}", fmt::join(members, ", ")),
                          {},
                          {}};
      startLoop(j, std::move(members), observation.time);
      loops_[j].events.push_back(std::move(chosen));
    }
    loops_[j].heard = heardCount;
  }
  Loop& loop = loops_[j];
  if (own != nullptr && params_.camcov.claims > 0.0) {
    heardClaims(*own, j, observation.time);
    loop.memberClaims.clear();
    for (std::size_t i : loop.members)
      loop.memberClaims.push_back(loop.claims[i]);
    loop.controller->setClaims(loop.memberClaims);
    yieldIfOutbid(j, observation.cameras[j], observation.time);
  }
  loop.planned.resize(loop.members.size());
  if (own == nullptr && !loop.scene) {
    // The whole team with the true world: the simulator's measurements serve as they are.
    loop.controller->control(observation, loop.planned);
  } else {
    loop.memberPoses.clear();
    for (std::size_t i : loop.members)
      loop.memberPoses.push_back(loop.believed[i]);
    // Nothing measured for this camera's world or team: its loop sweeps it itself.
    const Observation mine{observation.time,
                           plannedIn(own != nullptr ? own->world : observation.world, loop),
                           loop.memberPoses};
    loop.controller->control(mine, loop.planned);
  }
  command = loop.planned[loop.self];
  loop.controllerEvents.clear();
  loop.controller->takeEvents(loop.controllerEvents);
  for (ControlEvent& e : loop.controllerEvents) {
    // Its own events, and its team decisions as its own: what it planned for the others is
    // not what they do.
    if (e.camera != -1 && e.camera != static_cast<int>(loop.self)) continue;
    e.camera = static_cast<int>(j);
    loop.events.push_back(std::move(e));
  }
}

}  // namespace camcov::control
