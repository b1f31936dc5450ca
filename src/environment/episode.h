#pragma once
// One run of one scene, stepped by a caller that chooses the cameras' commands itself — a
// learning policy, a person — rather than by a method's controller (sim::simulate). The
// simulator is the batch's own (sim::Simulation): the same saturation, safety layer,
// boundary and measurement, so an episode whose commands are a method's is that method's
// run, to the bit (method_policy.h).
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "control/controller.h"
#include "params/parameters.h"
#include "scene/scene.h"
#include "sim/simulator.h"

namespace camcov::environment {

class Episode {
 public:
  // Starts at t = 0. The scene is shared: many episodes may run the same one.
  Episode(std::shared_ptr<const scene::Scene> scene, const params::Parameters& params);
  ~Episode();
  Episode(const Episode&) = delete;
  Episode& operator=(const Episode&) = delete;

  const scene::Scene& scene() const { return *scene_; }
  const params::Parameters& params() const { return params_; }

  // The present instant t_k = k · dt, as a controller sees it: the world, the poses, S(t) and
  // the reward's terms, measured. Valid until the next step().
  control::Observation observation() const { return simulation_->observation(); }
  // The present instant as the run is scored (the true world): what a learner is rewarded by,
  // also under limited knowledge, where observation() holds the known world.
  control::Observation scored() const { return simulation_->scored(); }
  int index() const { return simulation_->index(); }
  // Instants after t = 0 in the run (sim.duration / dt): the number of steps an episode takes.
  int steps() const { return simulation_->steps(); }
  // True once the last instant is reached; it takes no commands.
  bool finished() const { return simulation_->atLastInstant() || simulation_->finished(); }
  // Records the last instant, which completes the run's accounting (summary()'s averages).
  // Once finished(), after the last observation is read: the observation's time moves on.
  void close();

  // What the simulator raised at the present instant; a policy's controller adds its own.
  std::vector<control::ControlEvent>& events() { return simulation_->events(); }

  // Commands for [t_k, t_k+1) — one per camera, saturated to its limits and passed through the
  // safety layer; a non-finite one holds that camera still and is an event — then t_k+1,
  // measured. std::logic_error once finished().
  void step(std::span<const scene::CameraCommand> commands);

  // The run so far; its averages (eq. (4)) once closed.
  sim::RunSummary summary() const;

 private:
  std::shared_ptr<const scene::Scene> scene_;
  params::Parameters params_;
  std::unique_ptr<sim::Simulation> simulation_;
  // An episode records nothing, so no camera's goal matters: none is passed on.
  std::vector<std::optional<geometry::Pose>> noGoals_;
};

}  // namespace camcov::environment
