// `camcov optimum SCENE [--budget N] [--seed S] [--time T] [-o FILE.json] [--poses FILE.json]`:
// the offline reference for a scene that holds still (issue 19; planners/offline_optimum.h):
// the best team pose a long search finds for the reward at time T, its terms, how it was
// found and how the best grew with the budget. Written atomically; the poses also in the
// format `camcov inspect --cameras` reads.
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/command.h"
#include "cli/parameter_options.h"
#include "kinematics/kinematics.h"
#include "params/parameter_table.h"
#include "planners/offline_optimum.h"
#include "records/atomic_file.h"
#include "reward/reward_model.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/random.h"

namespace camcov::cli {
namespace {

struct OptimumCommandOptions {
  std::string scene;
  double time = 0.0;
  std::int64_t budget = planners::OptimumOptions{}.budget;
  std::uint64_t seed = 1;
  std::string out;
  std::string poses;
  ParameterOptions parameters;
};

nlohmann::json poseList(const std::vector<geometry::Pose>& poses) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& p : poses)
    list.push_back({{"x", p.x}, {"y", p.y}, {"yaw_deg", geometry::radToDeg(p.yaw)}});
  return list;
}

int optimum(const OptimumCommandOptions& o) {
  const scene::SceneFile file = scene::loadSceneFile(o.scene);
  const scene::Scene& s = file.scene;
  const params::Parameters p = o.parameters.resolve();
  const kinematics::World world = kinematics::Kinematics(s).worldAt(o.time);
  reward::RewardModel model(p.reward, scene::halfFovs(s));
  model.setWorld(world);
  planners::StateValidity validity(p.planner.d1);
  validity.setWorld(world);
  planners::OptimumOptions options;
  options.budget = o.budget;
  options.samplesPerCamera = p.global.K;
  Random random(o.seed);
  const auto best = planners::searchOptimum(model, validity, s.cameras.size(), options, random);
  if (!best) {
    throw InputError(
        fmt::format("{}: no valid pose for every camera was found at t = {} s", o.scene, o.time));
  }

  nlohmann::json curve = nlohmann::json::array();
  for (const auto& step : best->curve)
    curve.push_back(
        {{"evaluations", step.evaluations}, {"reward", step.reward}, {"coverage", step.coverage}});
  const nlohmann::json j = {
      {"format", "camcov-optimum/1"},
      {"note",
       "the best team pose a random, local search found: a reference, not a proof of "
       "optimality; the curve shows how the best grew with the budget"},
      {"scene", {{"name", s.name}, {"file", o.scene}, {"hash", file.hash}}},
      {"time", o.time},
      {"seed", o.seed},
      {"budget", o.budget},
      {"parameters", params::toJson(p)},
      {"best",
       {{"poses", poseList(best->poses)},
        {"coverage", best->terms.coverage},
        {"utilization", best->terms.utilization},
        {"repulsion", best->terms.repulsion},
        {"reward", best->terms.reward}}},
      {"found",
       {{"round", best->foundInRound}, {"by", best->foundBy}, {"evaluations", best->foundAt}}},
      {"rounds", best->rounds},
      {"evaluations", best->evaluations},
      {"curve", curve}};
  if (!o.out.empty()) records::writeFileAtomically(o.out, j.dump(1) + "\n");
  if (!o.poses.empty()) records::writeFileAtomically(o.poses, poseList(best->poses).dump(1) + "\n");
  std::cout << fmt::format(
      "{} at t = {} s: coverage {:.4f}, reward {:.4f}; found in round {} of {} by {} after {} "
      "of {} evaluations\n",
      s.name, o.time, best->terms.coverage, best->terms.reward, best->foundInRound, best->rounds,
      best->foundBy, best->foundAt, best->evaluations);
  for (const std::string* f : {&o.out, &o.poses}) {
    if (!f->empty()) std::cout << "  -> " << *f << "\n";
  }
  return 0;
}

}  // namespace

Registration addOptimumCommand(CLI::App& app) {
  auto o = std::make_shared<OptimumCommandOptions>();
  auto* cmd = app.add_subcommand(
      "optimum",
      "Search long for the best team pose at one instant: an offline reference for scenes "
      "that hold still (issue 19)");
  cmd->add_option("scene", o->scene, "scene file (JSON)")->required();
  cmd->add_option("--budget", o->budget,
                  "reward evaluations to spend (rounds of Algorithm 2 with K samples per camera, "
                  "each improved camera by camera until it stops improving)")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1} << 40))
      ->capture_default_str();
  cmd->add_option("--seed,-s", o->seed, "random seed of the search")->capture_default_str();
  cmd->add_option("--time", o->time, "the instant to optimize, s")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--out,-o", o->out, "write the result here (JSON)");
  cmd->add_option("--poses", o->poses,
                  "write the best poses here, as `camcov inspect --cameras` reads them");
  o->parameters.addTo(*cmd);
  return {cmd, [o] { return optimum(*o); }};
}

}  // namespace camcov::cli
