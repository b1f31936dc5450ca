#pragma once
// The paper's method (section V, Fig. 2). At t = 0 and every T1 seconds, global optimization
// (Algorithm 2) proposes a pose per camera; if its reward beats the reward of what the team
// is committed to (goals of cameras following a plan, poses of the others) by the factor τ,
// goals are assigned by the Hungarian method (cost: estimated travel time), one PRM* roadmap
// is built and every camera's path is queried from it. Cameras with a plan follow it with
// artificial potentials while the local optimizer keeps refining their goals; the others do
// local optimization (gradient ascent) directly.
//
// Events raised (event_kind.h): Global at every global optimization, with both rewards, its
// reason the decision; Plan, PlanFailed, PlanCompleted, PlanAborted; Replan when the refined
// goal drifted more than d1 from the path.
#include <memory>
#include <string>
#include <vector>

#include "control/camcov_choices.h"
#include "control/controller.h"
#include "control/event_kind.h"
#include "control/goal_assignment.h"
#include "params/parameters.h"
#include "planners/local_optimizer.h"
#include "planners/motion_planner.h"
#include "planners/plan_executor.h"
#include "planners/state_validity.h"
#include "reward/reward_model.h"
#include "scene/scene.h"
#include "util/random.h"
#include "util/run_threads.h"

namespace camcov::control {

// Our method (`--method camcov`) is this loop with the choices of params.camcov
// (docs/method.md, "Our method"): the global candidate (improved camera by camera when
// camcov.refine > 0) is judged by the coverage the team would average over the next H seconds
// (or over the whole trip where it takes longer), transit included, against the same for what
// it is committed to (camcov.horizon, while anything moves, else camcov.staticHorizon; the
// first global optimization waits one step to see whether anything moves); a camera goes straight
// to its goal where that move is valid (camcov.straightPaths) and on the way looks where it sees
// most (camcov.transitYaw). Its "global" events say so.
//
// Holds a reference to `scene`: the scene must outlive the controller.
class PaperController final : public Controller {
 public:
  enum class Variant { Paper, Camcov };

  // `start`: the time of the first instant it will see (a loop started during a run, as
  // camcov-dec starts one for a new neighbourhood, keeps its global steps T1 apart from then).
  // `threads`: how many its global step may score samples on (the same results with any).
  PaperController(const scene::Scene& scene, const params::Parameters& params, std::uint64_t seed,
                  Variant variant = Variant::Paper, double start = 0.0,
                  unsigned threads = runThreads());
  ~PaperController() override;

  void control(const Observation& observation, std::span<scene::CameraCommand> commands) override;
  std::optional<geometry::Pose> goal(std::size_t camera) const override;
  void takeEvents(std::vector<ControlEvent>& out) override;

  // camcov-dec: the teammates' claims on goals (goal_assignment.h), by camera of this
  // controller's team, for the assignments of its global steps from now on. A claimed goal is
  // also where the team is committed to have that teammate (the committed configuration is the
  // claim, not the plan this controller made for it, which the teammate never heard of).
  void setClaims(std::vector<std::optional<Claim>> claims) { claims_ = std::move(claims); }
  // camcov-dec: camera j, outbid for its goal, gives it up: it stops following its plan, and
  // the global step runs at the next instant (its period unchanged) to give it another.
  void giveUp(std::size_t j);

  // camcov-dec with camcov.ownPartOnly: this controller moves camera j only, its own (the others
  // are teammates that decide for themselves; it knows them as they last said): its global step
  // plans for the whole team as ours does, but judges j's part of that plan as j's move alone,
  // the teammates where the team is committed to have them, against staying; only j follows
  // plans and optimizes locally.
  void moveOwnCameraOnly(std::size_t j);

  // Does `candidate` beat `current` by the factor τ? For a non-positive current reward any
  // increase counts (τ·current would otherwise lower the bar).
  static bool improves(double candidate, double current, double tau);

 private:
  bool ours() const { return variant_ == Variant::Camcov; }
  // Camera j plans and moves here: every camera, or the own one only (moveOwnCameraOnly).
  bool moves(std::size_t j) const { return !own_ || j == *own_; }
  void globalOptimization(const Observation& observation);
  // Ours: improve the candidate, judge it over the horizon, plan if it wins.
  void judge(const Observation& observation, std::vector<geometry::Pose> candidate, double sampled);
  // The roadmap camera j queries, built for this planning event when first asked for.
  planners::Roadmap& roadmap(const Observation& observation, std::size_t j);
  // Ours: the turn rate that looks where camera j sees most on its way (camcov.transitYaw),
  // choosing among this many directions.
  static constexpr int kLookoutDirections = 16;
  double lookWhileMoving(std::span<geometry::Pose> team, std::size_t j, double plannedTurnRate);
  // Ours: the straight move to `goal` where it is valid.
  std::optional<std::vector<geometry::Pose>> straightPath(const Observation& observation,
                                                          std::size_t j,
                                                          const geometry::Pose& goal) const;
  void plan(const Observation& observation, const std::vector<geometry::Pose>& goals,
            const GoalAssignment& assignment);
  // A path and how it was found ("straight", "roadmap of N milestones").
  struct Route {
    std::vector<geometry::Pose> poses;
    std::string how;
  };
  // A route for every camera j to goals[j] (nullopt: none in the roadmap).
  std::vector<std::optional<Route>> planPaths(const Observation& observation,
                                              std::span<const geometry::Pose> goals);
  void startPlans(const Observation& observation, std::span<const geometry::Pose> goals,
                  std::vector<std::optional<Route>> routes);
  void refineGoals(const Observation& observation);
  void raise(double t, EventKind kind, int camera, std::string detail,
             std::vector<geometry::Pose> path = {}, std::string reason = {});
  std::vector<geometry::Pose> committedTeam(std::span<const geometry::Pose> cameras) const;
  // camcov-dec: camera j's claim, if a teammate's was heard (setClaims).
  const Claim* claimOf(std::size_t j) const {
    return j < claims_.size() && claims_[j] ? &*claims_[j] : nullptr;
  }

  const scene::Scene& scene_;
  params::Parameters params_;
  Variant variant_;
  MotionWatch motion_;  // ours: does anything move, and how?
  std::optional<bool> moving_;
  std::vector<scene::StepLimits> limits_;
  reward::RewardModel model_;
  reward::RewardModel forecastModel_;  // ours: the worlds the motion seen forecasts
  // One more model per thread the run may use (util/run_threads.h), for Algorithm 2's scores.
  std::vector<reward::RewardModel> helpers_;
  planners::StateValidity validity_;
  planners::LocalOptimizer local_;
  Random random_;
  std::vector<planners::PlanExecutor> executors_;
  // The last planning event's roadmap each camera queries (shared by cameras of equal θ).
  std::vector<std::shared_ptr<planners::Roadmap>> roadmapOf_;
  double nextGlobalTime_ = 0.0;
  bool globalNow_ = false;                    // camcov-dec: a camera gave up its goal
  std::vector<std::optional<Claim>> claims_;  // camcov-dec: empty, or one per camera
  std::optional<std::size_t> own_;            // camcov-dec: the one camera moved here, if so
  std::vector<ControlEvent> events_;
};

}  // namespace camcov::control
