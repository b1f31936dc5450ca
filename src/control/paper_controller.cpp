#include "control/paper_controller.h"

#include <fmt/format.h>
#include <cmath>

#include "control/local_controller.h"
#include "planners/global_optimizer.h"
#include "planners/hungarian.h"
#include "util/run_threads.h"

namespace camcov::control {

PaperController::PaperController(const scene::Scene& scene, const params::Parameters& params,
                                 std::uint64_t seed)
    : scene_(scene),
      params_(params),
      limits_(stepLimits(scene, params.sim.dt)),
      model_(params.reward, scene::halfFovs(scene)),
      validity_(params.planner.d1),
      local_(params.local),
      random_(seed),
      executors_(scene.cameras.size(), planners::PlanExecutor(params.potential, params.reward.d2)),
      roadmapOf_(scene.cameras.size()) {
  for (unsigned t = 1; t < runThreads(); ++t)
    helpers_.emplace_back(params.reward, scene::halfFovs(scene));
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

void PaperController::raise(double t, std::string kind, int camera, std::string detail,
                            std::vector<geometry::Pose> path, std::string reason) {
  events_.push_back(
      {t, std::move(kind), camera, std::move(detail), std::move(path), std::move(reason)});
}

std::vector<geometry::Pose> PaperController::committedTeam(
    std::span<const geometry::Pose> cameras) const {
  std::vector<geometry::Pose> team(cameras.begin(), cameras.end());
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (executors_[j].executing()) team[j] = executors_[j].goal();
  }
  return team;
}

void PaperController::globalOptimization(const Observation& observation) {
  for (auto& helper : helpers_)
    helper.setInstant(model_);
  const auto result = planners::optimizeGlobally(model_, validity_, observation.cameras.size(),
                                                 params_.global.K, random_, helpers_);
  const double current = model_.reward(committedTeam(observation.cameras));
  if (!result) {
    raise(observation.time, "global", -1, "no valid pose found for some camera", {},
          "no-valid-pose");
    return;
  }
  const Assignment assignment = assign(observation, result->poses);
  double candidate = result->reward;
  if (params_.global.horizon > 0.0) {
    candidate *= std::max(0.0, 1.0 - assignment.travelTime / params_.global.horizon);
  }
  const bool better = improves(candidate, current, params_.global.tau);
  raise(observation.time, "global", -1,
        fmt::format("global reward {:.4f} (travel {:.1f} s) vs current {:.4f}: {}", result->reward,
                    assignment.travelTime, current, better ? "replan" : "keep"),
        {}, better ? "replan" : "keep");
  if (better) plan(observation, result->poses, assignment);
}

PaperController::Assignment PaperController::assign(
    const Observation& observation, const std::vector<geometry::Pose>& goals) const {
  // Section V-B: estimated travel time, obstacles ignored.
  // Goal g was sampled for camera g's field of view: only a camera with the same θ takes it
  // (in a team of like cameras, any camera takes any goal, as in the paper).
  constexpr double kOtherFieldOfView = 1e12;  // s: never chosen while the identity is possible
  const std::size_t m = goals.size();
  std::vector<double> cost(m * m);
  for (std::size_t j = 0; j < m; ++j) {
    const auto& camera = scene_.cameras[j];
    for (std::size_t g = 0; g < m; ++g) {
      if (scene_.cameras[g].halfFov != camera.halfFov) {
        cost[j * m + g] = kOtherFieldOfView;
        continue;
      }
      const double travel =
          geometry::distance(observation.cameras[j].position(), goals[g].position()) /
          camera.maxVelocity;
      const double turn = std::abs(geometry::wrapAngle(goals[g].yaw - observation.cameras[j].yaw)) /
                          camera.maxAngularVelocity;
      cost[j * m + g] = std::max(travel, turn);
    }
  }
  Assignment result;
  result.goalOf = planners::solveAssignment(cost, static_cast<int>(m), static_cast<int>(m));
  for (std::size_t j = 0; j < m; ++j) {
    result.travelTime = std::max(result.travelTime, cost[j * m + result.goalOf[j]]);
  }
  return result;
}

void PaperController::plan(const Observation& observation, const std::vector<geometry::Pose>& goals,
                           const Assignment& assignment) {
  const std::size_t m = goals.size();
  // Section V-C: one roadmap for this planning event, queried by every camera — one per
  // field of view in a team of unlike cameras, since eq. (10)'s cost depends on θ.
  for (std::size_t j = 0; j < m; ++j) {
    const double theta = scene_.cameras[j].halfFov;
    roadmapOf_[j] = nullptr;
    for (std::size_t i = 0; i < j && !roadmapOf_[j]; ++i) {
      if (scene_.cameras[i].halfFov == theta) roadmapOf_[j] = roadmapOf_[i];
    }
    if (!roadmapOf_[j]) {
      roadmapOf_[j] =
          std::make_shared<planners::Roadmap>(observation.world, params_, theta, random_.fork());
    }
  }
  for (std::size_t j = 0; j < m; ++j) {
    const geometry::Pose& target = goals[assignment.goalOf[j]];
    auto path = roadmapOf_[j]->query(observation.cameras[j], target);
    if (!path) {
      executors_[j].stop();
      raise(observation.time, "plan-failed", static_cast<int>(j),
            "goal not reachable in the roadmap");
      continue;
    }
    raise(observation.time, "plan", static_cast<int>(j),
          fmt::format("{} waypoints to ({:.2f}, {:.2f}, {:.1f}°), roadmap of {} milestones",
                      path->size(), target.x, target.y, geometry::radToDeg(target.yaw),
                      roadmapOf_[j]->milestones()),
          *path);
    executors_[j].start(std::move(*path), observation.time);
  }
}

void PaperController::refineGoals(const Observation& observation) {
  // Section V-D: goals keep being refined by the local optimizer, against the team's
  // committed configuration, so a reached goal is a current local optimum.
  std::vector<geometry::Pose> team = committedTeam(observation.cameras);
  std::uint64_t executing = 0;
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (executors_[j].executing()) executing |= std::uint64_t{1} << j;
  }
  if (executing == 0) return;
  local_.improve(model_, team, executing, limits_);
  for (std::size_t j = 0; j < team.size(); ++j) {
    if (((executing >> j) & 1u) == 0) continue;
    planners::PlanExecutor& executor = executors_[j];
    const geometry::Pose planned = executor.path().back();
    executor.refineGoal(team[j]);
    // A goal that wandered off the plan is reached through the roadmap again.
    if (roadmapOf_[j] &&
        geometry::distance(planned.position(), team[j].position()) > params_.planner.d1) {
      if (auto path = roadmapOf_[j]->query(observation.cameras[j], team[j])) {
        raise(observation.time, "replan", static_cast<int>(j), "refined goal moved beyond d1",
              *path);
        executor.start(std::move(*path), observation.time);
      }
    }
  }
}

void PaperController::control(const Observation& observation,
                              std::span<kinematics::CameraCommand> commands) {
  takeInstant(model_, observation);
  validity_.setWorld(observation.world);
  const double t = observation.time;
  // Global optimization at t = 0 and every T1 (half a step of slack against rounding).
  if (t + 0.5 * params_.sim.dt >= nextGlobalTime_) {
    nextGlobalTime_ += params_.global.T1;
    globalOptimization(observation);
  }
  refineGoals(observation);

  std::vector<geometry::Pose> team(observation.cameras.begin(), observation.cameras.end());
  std::uint64_t idle = 0;
  std::vector<geometry::Pose> others;
  for (std::size_t j = 0; j < team.size(); ++j) {
    planners::PlanExecutor& executor = executors_[j];
    if (executor.executing()) {
      others.assign(team.begin(), team.end());
      others.erase(others.begin() + static_cast<std::ptrdiff_t>(j));
      commands[j] = executor.step(team[j], observation.world, others, scene_.cameras[j].maxVelocity,
                                  params_.sim.dt, t);
      if (executor.status() == planners::PlanExecutor::Status::Completed) {
        raise(t, "plan-completed", static_cast<int>(j), "goal reached");
      } else if (executor.status() == planners::PlanExecutor::Status::Aborted) {
        raise(t, "plan-aborted", static_cast<int>(j),
              fmt::format("no progress for T3 = {} s", params_.potential.T3));
      }
    }
    if (!executor.executing()) idle |= std::uint64_t{1} << j;
  }
  if (idle != 0) {
    std::vector<geometry::Pose> improved = team;
    local_.improve(model_, improved, idle, limits_);
    for (std::size_t j = 0; j < team.size(); ++j) {
      if ((idle >> j) & 1u) commands[j] = commandTowards(team[j], improved[j], params_.sim.dt);
    }
  }
}

}  // namespace camcov::control
