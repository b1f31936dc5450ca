#include "control/paper_controller.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "control/goal_assignment.h"
#include "control/local_controller.h"
#include "planners/global_optimizer.h"
#include "planners/team_improvement.h"

namespace camcov::control {

PaperController::PaperController(const scene::Scene& scene, const params::Parameters& params,
                                 std::uint64_t seed, Variant variant, double start,
                                 unsigned threads)
    : scene_(scene),
      params_(params),
      variant_(variant),
      limits_(stepLimits(scene, params.sim.dt)),
      model_(params.reward, scene::lenses(scene)),
      forecastModel_(params.reward, scene::lenses(scene)),
      validity_(params.planner.d1),
      local_(params.local, variant == Variant::Camcov && params.camcov.compass
                               ? planners::LocalOptimizer::Search::Compass
                               : planners::LocalOptimizer::Search::Gradient),
      random_(seed),
      executors_(scene.cameras.size(), planners::PlanExecutor(params.potential, params.reward.d2)),
      roadmapOf_(scene.cameras.size()),
      // Ours waits one step to see whether anything moves.
      nextGlobalTime_(start + (variant == Variant::Camcov ? params.sim.dt : 0.0)) {
  for (unsigned t = 1; t < threads; ++t)
    helpers_.emplace_back(params.reward, scene::lenses(scene));
  if (ours()) {
    model_.setDetail(params.camcov.detail);
    forecastModel_.setDetail(params.camcov.detail);
    for (auto& helper : helpers_)
      helper.setDetail(params.camcov.detail);
  }
}

PaperController::~PaperController() = default;

bool PaperController::improves(double candidate, double current, double tau) {
  return current > 0.0 ? candidate > tau * current : candidate > current;
}

std::optional<geometry::Pose> PaperController::goal(std::size_t camera) const {
  if (!executors_[camera].executing()) return std::nullopt;
  return executors_[camera].goal();
}

void PaperController::takeEvents(std::vector<ControlEvent>& out) {
  for (auto& e : events_)
    out.push_back(std::move(e));
  events_.clear();
}

void PaperController::raise(double t, EventKind kind, int camera, std::string detail,
                            std::vector<geometry::Pose> path, std::string reason) {
  events_.push_back({t, std::string(eventName(kind)), camera, std::move(detail), std::move(path),
                     std::move(reason)});
}

void PaperController::giveUp(std::size_t j) {
  executors_[j].stop();
  globalNow_ = true;
}

std::vector<geometry::Pose> PaperController::committedTeam(
    std::span<const geometry::Pose> cameras) const {
  std::vector<geometry::Pose> team(cameras.begin(), cameras.end());
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (const Claim* claim = claimOf(j)) {
      team[j] = claim->goal;
    } else if (executors_[j].executing()) {
      team[j] = executors_[j].goal();
    }
  }
  return team;
}

void PaperController::moveOwnCameraOnly(std::size_t j) {
  own_ = j;
}

void PaperController::globalOptimization(const Observation& observation) {
  for (auto& helper : helpers_)
    helper.setInstant(model_);
  const auto result = planners::optimizeGlobally(model_, validity_, observation.cameras.size(),
                                                 params_.global.K, random_, helpers_);
  if (ours() && result) return judge(observation, result->poses, result->reward);
  const double current = model_.reward(committedTeam(observation.cameras));
  if (!result) {
    raise(observation.time, EventKind::Global, -1, "no valid pose found for some camera", {},
          std::string(kDecisionNoValidPose));
    return;
  }
  const GoalAssignment assignment = assignGoals(scene_, observation.cameras, result->poses);
  double candidate = result->reward;
  if (params_.global.horizon > 0.0) {
    candidate *= std::max(0.0, 1.0 - assignment.travelTime / params_.global.horizon);
  }
  const bool better = improves(candidate, current, params_.global.tau);
  raise(observation.time, EventKind::Global, -1,
        fmt::format("global reward {:.4f} (travel {:.1f} s) vs current {:.4f}: {}", result->reward,
                    assignment.travelTime, current, better ? kDecisionReplan : kDecisionKeep),
        {}, std::string(better ? kDecisionReplan : kDecisionKeep));
  if (better) plan(observation, result->poses, assignment);
}

void PaperController::judge(const Observation& observation, std::vector<geometry::Pose> candidate,
                            double sampled) {
  const params::CamcovParams& ours = params_.camcov;
  const std::size_t m = candidate.size();
  double reward = sampled;
  planners::TeamImprovement(model_, validity_, ours.refine).refineAll(candidate, reward);
  // What the team is committed to: the cameras that follow a plan at its goal, the others
  // where they are (improved the same way as the candidate when camcov.refine > 0).
  std::vector<geometry::Pose> kept = committedTeam(observation.cameras);
  scene::CameraSet idle;
  for (std::size_t j = 0; j < m; ++j) {
    if (!executors_[j].executing() && claimOf(j) == nullptr) idle.insert(j);
  }
  double keptReward = model_.reward(kept);
  planners::TeamImprovement(model_, validity_, ours.refine).refineAll(kept, keptReward, idle);

  const GoalAssignment assignment =
      assignGoals(scene_, observation.cameras, candidate, claims_, params_.reward.d2);
  std::vector<geometry::Pose> goals(m);
  for (std::size_t j = 0; j < m; ++j)
    goals[j] = candidate[assignment.goalOf[j]];
  // The paths first, so that the transit is judged along them; a camera with none stays.
  auto routes = planPaths(observation, goals);
  std::vector<std::vector<geometry::Pose>> goPaths(m), keepPaths(m);
  std::vector<double> goTravel(m), keepTravel(m);
  double longest = 0.0;
  for (std::size_t j = 0; j < m; ++j) {
    const auto& camera = scene_.cameras[j];
    const geometry::Pose& now = observation.cameras[j];
    keepPaths[j] = executors_[j].executing() && claimOf(j) == nullptr
                       ? executors_[j].pathLeft(now)
                       : std::vector<geometry::Pose>{now, kept[j]};
    // camcov-dec: a teammate that claimed a goal goes there whatever this camera decides, and a
    // controller that moves its own camera only judges that camera's move alone: the others
    // keep to what they are committed to in both options.
    goPaths[j] = claimOf(j) != nullptr || !moves(j) ? keepPaths[j]
                 : routes[j]                        ? routes[j]->poses
                                                    : std::vector<geometry::Pose>{now};
    goTravel[j] = pathTravelTime(goPaths[j], camera);
    keepTravel[j] = pathTravelTime(keepPaths[j], camera);
    longest = std::max(longest, goTravel[j]);
  }
  // The window is H, or the whole trip where the trip is longer: both options are judged over
  // the same time, the transit's coverage included, and a far goal is never refused for its
  // distance alone (a cliff at H left teams that start far from everything standing still).
  const double horizon =
      std::max(moving_.value_or(true) ? ours.horizon : ours.staticHorizon, longest);
  const TeamMove goMove{goPaths, goTravel}, keepMove{keepPaths, keepTravel};
  const double go = averageCoverageAhead(model_, goMove, horizon, ours.transitSamples);
  double stay = averageCoverageAhead(model_, keepMove, horizon, ours.transitSamples);
  // The candidate was sampled to fit the world as it stands, so judged there it shows its best;
  // the committed team was not, and judged there alone it misses what is on its way into view
  // (dynamic1: a target about to drive across a camera's field of view). So staying is also
  // judged as things go on moving, and credited with the better of the two.
  std::string forecastNote;
  if (ours.forecastStay) {
    if (const Forecast forecast = motion_.forecast(geometry::boundingBox(scene_.boundary));
        forecast.moves()) {
      const double moving = forecastCoverageAhead(forecastModel_, forecast, keepMove, horizon);
      forecastNote = fmt::format(" ({:.4f} as things stand, {:.4f} as they move)", stay, moving);
      stay = std::max(stay, moving);
    }
  }
  const bool better = go > stay + ours.margin * std::abs(stay);
  raise(observation.time, EventKind::Global, -1,
        fmt::format("global reward {:.4f} ({:.4f} sampled, travel {:.1f} s); coverage over the "
                    "next {:g} s: {:.4f} vs {:.4f} kept{}: {}",
                    reward, sampled, longest, horizon, go, stay, forecastNote,
                    better ? kDecisionReplan : kDecisionKeep),
        {}, std::string(better ? kDecisionReplan : kDecisionKeep));
  if (better) startPlans(observation, goals, std::move(routes));
}

double PaperController::lookWhileMoving(std::span<geometry::Pose> team, std::size_t j,
                                        double plannedTurnRate) {
  const auto& camera = scene_.cameras[j];
  const double dt = params_.sim.dt, maxTurn = camera.stepLimits(dt).maxRotation;
  const planners::PlanExecutor& executor = executors_[j];
  const double planned =
      geometry::wrapAngle(team[j].yaw + std::clamp(plannedTurnRate * dt, -maxTurn, maxTurn));
  const double timeLeft = executor.distanceLeft(team[j]) / camera.maxVelocity - dt;
  const double yaw = lookoutYaw(model_, team, j, planned, executor.goal().yaw, timeLeft,
                                camera.maxAngularVelocity, kLookoutDirections);
  return geometry::wrapAngle(yaw - team[j].yaw) / dt;
}

planners::Roadmap& PaperController::roadmap(const Observation& observation, std::size_t j) {
  // Section V-C: one roadmap for this planning event, queried by every camera — one per
  // lens in a team of unlike cameras, since eq. (10)'s cost depends on θ.
  if (!roadmapOf_[j]) {
    const scene::Lens& lens = scene_.cameras[j].lens;
    for (std::size_t i = 0; i < roadmapOf_.size() && !roadmapOf_[j]; ++i) {
      if (i != j && roadmapOf_[i] && scene_.cameras[i].lens == lens) roadmapOf_[j] = roadmapOf_[i];
    }
    if (!roadmapOf_[j]) {
      // A world that is a part of the room (camcov-dec's region) gets its share of T2's
      // milestones.
      const double share =
          std::min(1.0, geometry::area(geometry::boundingBox(observation.world.boundary)) /
                            geometry::area(geometry::boundingBox(scene_.boundary)));
      roadmapOf_[j] =
          std::make_shared<planners::Roadmap>(observation.world, params_, lens, random_.fork(),
                                              share, ours() ? params_.camcov.detail : 0.0);
    }
  }
  return *roadmapOf_[j];
}

std::optional<std::vector<geometry::Pose>> PaperController::straightPath(
    const Observation& observation, std::size_t j, const geometry::Pose& goal) const {
  const geometry::Pose& start = observation.cameras[j];
  if (!ours() || !params_.camcov.straightPaths ||
      !validity_.isValidMotion(start.position(), goal.position())) {
    return std::nullopt;
  }
  return std::vector<geometry::Pose>{start, goal};
}

std::vector<std::optional<PaperController::Route>> PaperController::planPaths(
    const Observation& observation, std::span<const geometry::Pose> goals) {
  const std::size_t m = goals.size();
  for (auto& r : roadmapOf_)
    r = nullptr;
  // The paper builds the roadmaps up front; ours only where a straight move will not do.
  if (!ours()) {
    for (std::size_t j = 0; j < m; ++j)
      roadmap(observation, j);
  }
  std::vector<std::optional<Route>> routes(m);
  for (std::size_t j = 0; j < m; ++j) {
    if (!moves(j)) continue;
    if (auto straight = straightPath(observation, j, goals[j])) {
      routes[j] = Route{std::move(*straight), "straight"};
      continue;
    }
    planners::Roadmap& r = roadmap(observation, j);
    if (auto path = r.query(observation.cameras[j], goals[j])) {
      routes[j] = Route{std::move(*path), fmt::format("roadmap of {} milestones", r.milestones())};
    }
  }
  return routes;
}

void PaperController::startPlans(const Observation& observation,
                                 std::span<const geometry::Pose> goals,
                                 std::vector<std::optional<Route>> routes) {
  for (std::size_t j = 0; j < goals.size(); ++j) {
    if (!moves(j)) continue;
    const geometry::Pose& target = goals[j];
    if (!routes[j]) {
      executors_[j].stop();
      raise(observation.time, EventKind::PlanFailed, static_cast<int>(j),
            "goal not reachable in the roadmap");
      continue;
    }
    Route& route = *routes[j];
    raise(observation.time, EventKind::Plan, static_cast<int>(j),
          fmt::format("{} waypoints to ({:.2f}, {:.2f}, {:.1f}°), {}", route.poses.size(), target.x,
                      target.y, geometry::radToDeg(target.yaw), route.how),
          route.poses);
    executors_[j].start(std::move(route.poses), observation.time);
  }
}

void PaperController::plan(const Observation& observation, const std::vector<geometry::Pose>& goals,
                           const GoalAssignment& assignment) {
  std::vector<geometry::Pose> targets(goals.size());
  for (std::size_t j = 0; j < goals.size(); ++j)
    targets[j] = goals[assignment.goalOf[j]];
  startPlans(observation, targets, planPaths(observation, targets));
}

void PaperController::refineGoals(const Observation& observation) {
  // Section V-D: goals keep being refined by the local optimizer, against the team's
  // committed configuration, so a reached goal is a current local optimum.
  std::vector<geometry::Pose> team = committedTeam(observation.cameras);
  scene::CameraSet executing;
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (executors_[j].executing()) executing.insert(j);
  }
  if (executing.empty()) return;
  local_.improve(model_, team, executing, limits_);
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (!executing.contains(j)) continue;
    planners::PlanExecutor& executor = executors_[j];
    const geometry::Pose planned = executor.path().back();
    executor.refineGoal(team[j]);
    // A goal that wandered off the plan is reached again: straight (ours, where valid), else
    // through the roadmap.
    if (geometry::distance(planned.position(), team[j].position()) <= params_.planner.d1) continue;
    auto path = straightPath(observation, j, team[j]);
    if (!path && roadmapOf_[j]) path = roadmapOf_[j]->query(observation.cameras[j], team[j]);
    if (path) {
      raise(observation.time, EventKind::Replan, static_cast<int>(j),
            "refined goal moved beyond d1", *path);
      executor.start(std::move(*path), observation.time);
    }
  }
}

void PaperController::control(const Observation& observation,
                              std::span<scene::CameraCommand> commands) {
  takeInstant(model_, observation);
  validity_.setWorld(observation.world);
  if (ours()) moving_ = motion_.see(observation.world);
  const double t = observation.time;
  // Global optimization at t = 0 and every T1 (half a step of slack against rounding).
  const bool due = t + 0.5 * params_.sim.dt >= nextGlobalTime_;
  if (due) nextGlobalTime_ += params_.global.T1;
  if (due || globalNow_) {
    globalNow_ = false;
    globalOptimization(observation);
  }
  refineGoals(observation);

  std::vector<geometry::Pose> team(observation.cameras.begin(), observation.cameras.end());
  scene::CameraSet idle;
  std::vector<geometry::Pose> others;
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (!moves(j)) {
      commands[j] = {};  // a teammate moves itself
      continue;
    }
    planners::PlanExecutor& executor = executors_[j];
    if (executor.executing()) {
      others.assign(team.begin(), team.end());
      others.erase(others.begin() + static_cast<std::ptrdiff_t>(j));
      commands[j] = executor.step(team[j], observation.world, others, scene_.cameras[j].maxVelocity,
                                  params_.sim.dt, t);
      if (ours() && params_.camcov.transitYaw && executor.executing()) {
        commands[j].angularVelocity = lookWhileMoving(team, j, commands[j].angularVelocity);
      }
      if (executor.status() == planners::PlanExecutor::Status::Completed) {
        raise(t, EventKind::PlanCompleted, static_cast<int>(j), "goal reached");
      } else if (executor.status() == planners::PlanExecutor::Status::Aborted) {
        raise(t, EventKind::PlanAborted, static_cast<int>(j),
              fmt::format("no progress for T3 = {} s", params_.potential.T3));
      }
    }
    if (!executor.executing()) idle.insert(j);
  }
  if (!idle.empty()) {
    std::vector<geometry::Pose> improved = team;
    local_.improve(model_, improved, idle, limits_);
    for (std::size_t j = 0; j < team.size(); ++j) {
      if (idle.contains(j)) commands[j] = commandTowards(team[j], improved[j], params_.sim.dt);
    }
  }
}

}  // namespace camcov::control
