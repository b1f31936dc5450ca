#pragma once
// The paper's method (section V, Fig. 2). At t = 0 and every T1 seconds, global optimization
// (Algorithm 2) proposes a pose per camera; if its reward beats the reward of what the team
// is committed to (goals of cameras following a plan, poses of the others) by the factor τ,
// goals are assigned by the Hungarian method (cost: estimated travel time), one PRM* roadmap
// is built and every camera's path is queried from it. Cameras with a plan follow it with
// artificial potentials while the local optimizer keeps refining their goals; the others do
// local optimization (gradient ascent) directly.
//
// Events raised: "global" (every global optimization, with both rewards; its reason is the
// decision: "replan", "keep" or "no-valid-pose"), "plan" (a path),
// "plan-failed" (no path in the roadmap), "plan-completed", "plan-aborted" (no progress for
// T3), "replan" (the refined goal drifted more than d1 from the path: queried again).
#include <memory>
#include <vector>

#include "control/controller.h"
#include "params/parameters.h"
#include "planners/local_optimizer.h"
#include "planners/motion_planner.h"
#include "planners/plan_executor.h"
#include "planners/state_validity.h"
#include "reward/reward_model.h"
#include "scene/scene.h"
#include "util/random.h"

namespace camcov::control {

// Holds a reference to `scene`: the scene must outlive the controller.
class PaperController final : public Controller {
 public:
  PaperController(const scene::Scene& scene, const params::Parameters& params, std::uint64_t seed);
  ~PaperController() override;

  void control(const Observation& observation,
               std::span<kinematics::CameraCommand> commands) override;
  std::optional<geometry::Pose> goal(std::size_t camera) const override;
  void takeEvents(std::vector<ControlEvent>& out) override;

  // Does `candidate` beat `current` by the factor τ? For a non-positive current reward any
  // increase counts (τ·current would otherwise lower the bar).
  static bool improves(double candidate, double current, double tau);

 private:
  struct Assignment {
    std::vector<int> goalOf;  // camera j goes to goals[goalOf[j]]
    double travelTime = 0.0;  // the largest estimated travel time, s
  };

  void globalOptimization(const Observation& observation);
  Assignment assign(const Observation& observation, const std::vector<geometry::Pose>& goals) const;
  void plan(const Observation& observation, const std::vector<geometry::Pose>& goals,
            const Assignment& assignment);
  void refineGoals(const Observation& observation);
  void raise(double t, std::string kind, int camera, std::string detail,
             std::vector<geometry::Pose> path = {}, std::string reason = {});
  std::vector<geometry::Pose> committedTeam(std::span<const geometry::Pose> cameras) const;

  const scene::Scene& scene_;
  params::Parameters params_;
  std::vector<planners::StepLimits> limits_;
  reward::RewardModel model_;
  // One more model per thread the run may use (util/run_threads.h), for Algorithm 2's scores.
  std::vector<reward::RewardModel> helpers_;
  planners::StateValidity validity_;
  planners::LocalOptimizer local_;
  Random random_;
  std::vector<planners::PlanExecutor> executors_;
  // The last planning event's roadmap each camera queries (shared by cameras of equal θ).
  std::vector<std::shared_ptr<planners::Roadmap>> roadmapOf_;
  double nextGlobalTime_ = 0.0;
  std::vector<ControlEvent> events_;
};

}  // namespace camcov::control
