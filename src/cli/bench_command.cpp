// `camcov bench`: the main job. Every (scene, method, seed) of a folder of scenes, on all
// cores, resumable, shardable; then the summary and the OMPL benchmark logs.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

#include "batch/batch_plan.h"
#include "camcov/version.h"
#include "cli/bench_outputs.h"
#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/parameter_options.h"
#include "cli/progress.h"
#include "control/methods.h"
#include "records/atomic_file.h"

namespace camcov::cli {
namespace {

// The default batch's methods, comma-separated: the default of --methods.
std::string defaultMethods() {
  std::string names;
  for (const std::string& m : control::defaultMethods())
    names += (names.empty() ? "" : ",") + m;
  return names;
}

struct BenchOptions {
  std::vector<std::string> scenes{"scenes"};
  std::string methods = defaultMethods();
  std::uint64_t seeds = 5;
  double duration = -1.0;
  unsigned jobs = 0;
  std::string out = "bench-results";
  std::string shard;
  bool force = false;
  BenchOutputOptions outputs;
  ParameterOptions parameters;
  std::vector<std::string> argv;
};

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

// The batch's progress on stderr (progress.h), and where a resumed batch picks up.
class ProgressLine final : public batch::BatchObserver {
 public:
  explicit ProgressLine(std::string folder) : folder_(std::move(folder)) {}
  ~ProgressLine() override {
    if (progress_) progress_->close();
  }
  void resuming(const batch::Resumption& r) override {
    if (r.alreadyDone > 0) std::cerr << batch::describeResumption(r, folder_) << "\n";
    progress_.emplace(r.total, r.alreadyDone);
  }
  void finished(const batch::BatchJob& job, const records::JobOutcome& outcome) override {
    progress_->finished(outcome.failed ? fmt::format("{}: FAILED: {}", job.stem, outcome.error)
                                       : fmt::format("{}: coverage {:.3f}", job.stem,
                                                     outcome.summary.averageCoverage));
  }

 private:
  std::string folder_;
  std::optional<Progress> progress_;
};

int bench(const BenchOptions& o) {
  o.outputs.check();  // a bad --videos or --explorer fails now, not after the runs
  batch::BatchRequest request{o.scenes,
                              splitList(o.methods),
                              o.seeds,
                              o.parameters.resolve(),
                              batch::parseShard(o.shard),
                              o.argv,
                              {}};
  if (o.duration >= 0.0) request.parameters.sim.duration = o.duration;
  batch::BatchPlan plan = batch::planBatch(request, kVersion);
  o.outputs.referenceAmong(request.methods);  // and a bad --reference too
  const records::BatchFolder folder(o.out);
  {
    records::NewFolderGuard created(folder.root());  // kept once the manifest is written
    batch::prepareFolder(folder, plan.manifest, o.force);
    created.keep();
  }

  const batch::Shard& shard = request.shard;
  const unsigned workers = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  std::cerr << fmt::format(
      "camcov bench: {} scenes x {} methods x {} seeds = {} jobs{} on {} workers -> {}\n",
      plan.manifest.scenes.size(), request.methods.size(), o.seeds, plan.totalJobs,
      shard.count > 1
          ? fmt::format(" (shard {}/{}: {})", shard.index + 1, shard.count, plan.jobs.size())
          : "",
      workers, o.out);
  batch::BatchRun run;
  {
    ProgressLine progress(o.out);
    run = batch::runBatch(plan.jobs, folder, workers, progress);
  }
  const std::size_t failed = std::count_if(run.outcomes.begin(), run.outcomes.end(),
                                           [](const auto& j) { return j.failed; });
  if (shard.count > 1) {
    std::cout << fmt::format(
        "shard {}/{} done: {} jobs, {} failed. Combine the shards' folders "
        "with `camcov merge DIR... --out DIR`.\n",
        shard.index + 1, shard.count, plan.jobs.size(), failed);
    return failed ? 1 : 0;
  }
  return writeBenchOutputs(folder, plan.manifest, run.outcomes, o.outputs, workers);
}

}  // namespace

Registration addBenchCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "bench", "Run the methods on every scene for many seeds; write results, summary and logs");
  auto o = std::make_shared<BenchOptions>();
  cmd->add_option("--scenes", o->scenes, "scene folders or files")->capture_default_str();
  cmd->add_option("--methods", o->methods, "comma-separated names of methods")
      ->capture_default_str();
  cmd->add_option("--seeds", o->seeds, "seeds 1..N per scene and method")
      ->check(within(1, batch::kMaxSeeds))
      ->capture_default_str();
  cmd->add_option("--duration", o->duration, "simulated seconds per run (default: sim.duration)")
      ->check(within(0.0, 1e6));
  cmd->add_option("--jobs,-j", o->jobs, "worker threads (default: all cores)")
      ->check(within(0, 1024));
  cmd->add_option("--out,-o", o->out, "results folder")->capture_default_str();
  cmd->add_option("--shard", o->shard, "run only part K of N of the jobs (K/N, 1-based)");
  cmd->add_flag("--force", o->force,
                "run again jobs made with other parameters or by other code of a method");
  o->outputs.addTo(*cmd);
  o->parameters.addTo(*cmd);
  return {cmd, [o] {
            o->argv = invocation();
            return bench(*o);
          }};
}

}  // namespace camcov::cli
