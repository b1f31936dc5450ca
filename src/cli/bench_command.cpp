// `camcov bench`: the main job. Every (scene, method, seed) of a folder of scenes, on all
// cores, resumable, shardable; then the summary, logs, videos, pages and report
// (bench/run_bench.h does it all; this file is its options). A --set with a list of values
// (params/sweep.h) makes a study: one batch per setting in OUT/<key=value>, then the report of
// the settings side by side in OUT/report.html.
#include <filesystem>
#include <iostream>
#include <sstream>

#include "batch/batch_plan.h"
#include "bench/run_bench.h"
#include "cli/bench_output_options.h"
#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/parameter_options.h"
#include "cli/terminal_observer.h"
#include "params/sweep.h"
#include "records/batch_folder.h"
#include "reports/settings_report.h"
#include "scene/scene.h"
#include "util/input_error.h"

namespace camcov::cli {
namespace {

// Every setting checked before any runs; each a whole batch in its own folder, resumable as
// one; then the settings side by side (unless --no-report). Exit 1 if any job failed.
int runStudy(const bench::BenchRequest& base, const ParameterOptions& parameters,
             const std::vector<params::SweepSetting>& settings) {
  namespace fs = std::filesystem;
  if (!base.shard.empty())
    throw InputError("--shard with a list of values: shard each setting's folder instead");
  if (records::BatchFolder::holdsBatch(base.out)) {
    throw InputError(base.out +
                     ": holds one batch; a study writes a folder of settings, one "
                     "batch each: give another --out");
  }
  std::vector<params::Parameters> resolved;
  for (const auto& s : settings)
    resolved.push_back(parameters.resolve(s.assignments));
  std::vector<fs::path> folders;
  bool failed = false;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    bench::BenchRequest request = base;
    request.parameters = resolved[i];
    request.out = (fs::path(base.out) / settings[i].name).string();
    folders.push_back(request.out);
    std::cerr << "== setting " << i + 1 << " of " << settings.size() << ": " << settings[i].name
              << "\n";
    TerminalObserver terminal;
    failed = bench::runBench(request, terminal).failedJobs > 0 || failed;
  }
  if (!base.outputs.noReport) {
    const fs::path report = fs::path(base.out) / "report.html";
    reports::writeSettingsReport(folders, "", report);
    std::cout << "wrote " << report.string() << " (the settings side by side)\n";
  }
  return failed ? 1 : 0;
}

}  // namespace

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
  cmd->add_option("--jobs,-j", r.jobs, "worker threads (default: every core it may run on)")
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
            request.command = invocation();
            const auto settings = params::expandSweep(o->parameters.assignments());
            if (settings.size() == 1) {
              request.parameters = o->parameters.resolve();
              TerminalObserver terminal;
              return bench::runBench(request, terminal).failedJobs > 0 ? 1 : 0;
            }
            return runStudy(request, o->parameters, settings);
          }};
}

}  // namespace camcov::cli
