// `camcov bench`: the main job. Every (scene, method, seed) of a folder of scenes, on all
// cores, resumable, shardable; then the summary, logs, videos, pages and report
// (bench/run_bench.h does it all; this file is its options).
#include <sstream>

#include "batch/batch_plan.h"
#include "bench/run_bench.h"
#include "cli/bench_output_options.h"
#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/parameter_options.h"
#include "cli/terminal_observer.h"
#include "scene/scene.h"

namespace camcov::cli {

Registration addBenchCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "bench", "Run the methods on every scene for many seeds; write results, summary and logs");
  struct Options {
    bench::BenchRequest request;
    std::string methods;  // comma-separated
    ParameterOptions parameters;
  };
  auto o = std::make_shared<Options>();
  bench::BenchRequest& r = o->request;
  for (const std::string& m : r.methods)
    o->methods += (o->methods.empty() ? "" : ",") + m;
  cmd->add_option("--scenes", r.scenes, "scene folders or files")->capture_default_str();
  cmd->add_option("--methods", o->methods, "comma-separated names of methods")
      ->capture_default_str();
  cmd->add_option("--seeds", r.seeds, "seeds 1..N per scene and method")
      ->check(within(1, batch::kMaxSeeds))
      ->capture_default_str();
  cmd->add_option("--duration", r.duration,
                  "simulated seconds per run (default: a scene's own duration if it has one, else "
                  "sim.duration)")
      ->check(within(0.0, scene::kMaxDuration, false));
  cmd->add_option("--jobs,-j", r.jobs, "worker threads (default: all cores)")
      ->check(within(0, 1024));
  cmd->add_option("--out,-o", r.out, "results folder")->capture_default_str();
  cmd->add_option("--shard", r.shard, "run only part K of N of the jobs (K/N, 1-based)");
  cmd->add_flag("--force", r.force,
                "run again jobs made with other parameters or by other code of a method");
  addBenchOutputOptions(*cmd, r.outputs);
  o->parameters.addTo(*cmd);
  return {cmd, [o] {
            bench::BenchRequest request = o->request;
            request.methods.clear();
            std::stringstream list(o->methods);
            for (std::string item; std::getline(list, item, ',');)
              if (!item.empty()) request.methods.push_back(item);
            request.parameters = o->parameters.resolve();
            request.command = invocation();
            TerminalObserver terminal;
            return bench::runBench(request, terminal).failedJobs > 0 ? 1 : 0;
          }};
}

}  // namespace camcov::cli
