// `camcov optimum SCENE [--budget N] [--seed S] [--time T] [-o FILE.json] [--poses FILE.json]`:
// the offline reference for a scene that holds still (planners/offline_optimum.h):
// the best team pose a long search finds for the reward at time T, its terms, how it was
// found and how the best grew with the budget. Written atomically; the poses also in the
// format `camcov inspect --cameras` reads.
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "batch/scene_optimum.h"
#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/parameter_options.h"
#include "records/atomic_file.h"
#include "records/optimum_file.h"

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

int optimum(const OptimumCommandOptions& o) {
  const records::OptimumFile found =
      batch::searchSceneOptimum(o.scene, o.parameters.resolve(), o.time, o.budget, o.seed);
  const nlohmann::json j = records::optimumToJson(found);
  if (!o.out.empty()) records::writeFileAtomically(o.out, j.dump(1) + "\n");
  if (!o.poses.empty()) {
    records::writeFileAtomically(o.poses, j.at("best").at("poses").dump(1) + "\n");
  }
  const planners::OptimumResult& best = found.result;
  std::cout << fmt::format(
      "{} at t = {} s: coverage {:.4f}, reward {:.4f}; found in round {} of {} by {} after {} "
      "of {} evaluations\n",
      found.scene, o.time, best.terms.coverage, best.terms.reward, best.foundInRound, best.rounds,
      best.foundBy, best.foundAt, best.evaluations);
  std::cout << fmt::format(
      "  the team needs about {:.1f} s from its start to reach it (section V-B's estimate: "
      "straight at full speed, obstacles ignored)\n",
      found.travelTime);
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
      "that hold still");
  cmd->add_option("scene", o->scene, "scene file (JSON)")->required();
  cmd->add_option("--budget", o->budget,
                  "reward evaluations to spend (rounds of Algorithm 2 with K samples per camera, "
                  "each improved camera by camera until it stops improving)")
      ->check(within(1, 0x1p40))
      ->capture_default_str();
  cmd->add_option("--seed,-s", o->seed, "random seed of the search")->capture_default_str();
  cmd->add_option("--time", o->time, "the instant to optimize, s")
      ->check(within(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--out,-o", o->out, "write the result here (JSON)");
  cmd->add_option("--poses", o->poses,
                  "write the best poses here, as `camcov inspect --cameras` reads them");
  o->parameters.addTo(*cmd);
  return {cmd, [o] { return optimum(*o); }};
}

}  // namespace camcov::cli
