#include "batch/scene_optimum.h"

#include <fmt/format.h>

#include "control/goal_assignment.h"
#include "kinematics/kinematics.h"
#include "planners/state_validity.h"
#include "reward/reward_model.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/random.h"

namespace camcov::batch {

records::OptimumFile searchSceneOptimum(const std::filesystem::path& sceneFile,
                                        const params::Parameters& parameters, double time,
                                        std::int64_t budget, std::uint64_t seed) {
  return searchSceneOptimum(scene::loadSceneFile(sceneFile), sceneFile, parameters, time, budget,
                            seed);
}

records::OptimumFile searchSceneOptimum(const scene::SceneFile& file,
                                        const std::filesystem::path& sceneFile,
                                        const params::Parameters& parameters, double time,
                                        std::int64_t budget, std::uint64_t seed) {
  const scene::Scene& s = file.scene;
  const kinematics::World world = kinematics::Kinematics(s).worldAt(time);
  reward::RewardModel model(parameters.reward, scene::lenses(s));
  model.setWorld(world);
  planners::StateValidity validity(parameters.planner.d1);
  validity.setWorld(world);
  planners::OptimumOptions options;
  options.budget = budget;
  options.samplesPerCamera = parameters.global.K;
  Random random(seed);
  auto best = planners::searchOptimum(model, validity, s.cameras.size(), options, random);
  if (!best) {
    throw InputError(fmt::format("{}: no valid pose for every camera was found at t = {} s",
                                 sceneFile.string(), time));
  }
  std::vector<geometry::Pose> starts;
  for (const auto& camera : s.cameras)
    starts.push_back(camera.initial);
  const double travel = control::assignGoals(s, starts, best->poses).travelTime;
  return {s.name, sceneFile.string(), file.hash,        time,  seed,
          budget, parameters,         std::move(*best), travel};
}

}  // namespace camcov::batch
