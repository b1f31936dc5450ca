// `camcov bench`: the main job. Every (scene, method, seed) of a folder of scenes, on all
// cores, resumable, shardable; then the summary and the OMPL benchmark logs.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

#include "camcov/version.h"
#include "cli/batch_runner.h"
#include "cli/bench_outputs.h"
#include "cli/command.h"
#include "cli/parameter_options.h"
#include "control/methods.h"
#include "params/parameter_table.h"
#include "records/run_files.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/natural_order.h"

namespace camcov::cli {
namespace {

namespace fs = std::filesystem;

struct BenchOptions {
  std::vector<std::string> scenes{"scenes"};
  std::string methods = "paper,local";
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

// Folders contribute their *.json files in name order; files are taken as given.
std::vector<fs::path> sceneFiles(const std::vector<std::string>& inputs) {
  std::vector<fs::path> files;
  for (const auto& input : inputs) {
    if (fs::is_directory(input)) {
      std::vector<fs::path> found;
      for (const auto& e : fs::directory_iterator(input)) {
        if (e.path().extension() == ".json") found.push_back(e.path());
      }
      std::sort(found.begin(), found.end(), [](const fs::path& a, const fs::path& b) {
        return naturalLess(a.filename().string(), b.filename().string());
      });
      if (found.empty()) throw InputError(input + ": no scene files (*.json) in this folder");
      files.insert(files.end(), found.begin(), found.end());
    } else if (fs::exists(input)) {
      files.emplace_back(input);
    } else {
      throw InputError(input + ": no such scene file or folder");
    }
  }
  return files;
}

struct Shard {
  std::size_t index = 0;  // 0-based
  std::size_t count = 1;
};

Shard parseShard(const std::string& text) {
  if (text.empty()) return {};
  std::size_t k = 0, n = 0;
  char slash = 0, rest = 0;
  std::istringstream in(text);
  if (!(in >> k >> slash >> n) || slash != '/' || (in >> rest) || n == 0 || k == 0 || k > n) {
    throw InputError("--shard " + text + ": expected K/N with 1 <= K <= N");
  }
  return {k - 1, n};
}

int bench(const BenchOptions& o) {
  const std::vector<std::string> methods = splitList(o.methods);
  if (methods.empty()) throw InputError("--methods: name at least one method");
  for (const auto& m : methods)
    control::requireMethod(m);
  if (o.seeds == 0) throw InputError("--seeds must be at least 1");
  o.outputs.videoChoice();  // a bad --videos fails now, not after the runs
  const Shard shard = parseShard(o.shard);
  params::Parameters parameters = o.parameters.resolve();
  if (o.duration >= 0.0) parameters.sim.duration = o.duration;

  // Every scene is read and validated before anything runs: a typo fails in a second.
  records::BatchManifest manifest{kVersion, parameters, methods, o.seeds, {}, o.argv};
  std::vector<BatchJob> jobs;
  for (const fs::path& file : sceneFiles(o.scenes)) {
    const scene::SceneFile s = scene::loadSceneFile(file);
    manifest.scenes.push_back({s.scene.name, file.string(), s.hash});
  }
  for (const auto& entry : manifest.scenes) {
    for (const auto& method : methods) {
      for (std::uint64_t seed = 1; seed <= o.seeds; ++seed) {
        JobSpec spec{entry.file, method, seed, parameters};
        jobs.push_back({spec, entry.name, entry.hash, records::runStem(entry.name, method, seed)});
      }
    }
  }
  std::vector<BatchJob> mine;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    if (i % shard.count == shard.index) mine.push_back(jobs[i]);
  }

  const records::BatchFolder folder(o.out);
  if (const auto previous = folder.readManifest()) {
    if (params::toJson(previous->parameters) != params::toJson(parameters) && !o.force) {
      throw InputError(o.out +
                       " holds results made with other parameters; use another --out, "
                       "or --force to run those jobs again with the new ones");
    }
  }
  folder.removeStaleTemporaries();
  folder.writeManifest(manifest);

  const unsigned workers = o.jobs > 0 ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  std::cerr << fmt::format(
      "camcov bench: {} scenes x {} methods x {} seeds = {} jobs{} on {} workers -> {}\n",
      manifest.scenes.size(), methods.size(), o.seeds, jobs.size(),
      shard.count > 1 ? fmt::format(" (shard {}/{}: {})", shard.index + 1, shard.count, mine.size())
                      : "",
      workers, o.out);
  BatchRun run = runBatch(mine, folder, workers);
  auto timings = folder.readTimings();
  for (const auto& [stem, t] : run.timings)
    timings[stem] = t;
  folder.writeTimings(timings);

  const std::size_t failed = std::count_if(run.outcomes.begin(), run.outcomes.end(),
                                           [](const auto& j) { return j.failed; });
  if (shard.count > 1) {
    std::cout << fmt::format(
        "shard {}/{} done: {} jobs, {} failed. Combine the shards' folders "
        "with `camcov merge DIR... --out DIR`.\n",
        shard.index + 1, shard.count, mine.size(), failed);
    return failed ? 1 : 0;
  }
  return writeBenchOutputs(folder, manifest, run.outcomes, o.outputs, workers);
}

}  // namespace

Registration addBenchCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "bench", "Run both methods on every scene for many seeds; write results, summary and logs");
  auto o = std::make_shared<BenchOptions>();
  cmd->add_option("--scenes", o->scenes, "scene folders or files")->capture_default_str();
  cmd->add_option("--methods", o->methods, "comma-separated: paper, local")->capture_default_str();
  cmd->add_option("--seeds", o->seeds, "seeds 1..N per scene and method")->capture_default_str();
  cmd->add_option("--duration", o->duration, "simulated seconds per run (default: sim.duration)")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_option("--jobs,-j", o->jobs, "worker threads (default: all cores)");
  cmd->add_option("--out,-o", o->out, "results folder")->capture_default_str();
  cmd->add_option("--shard", o->shard, "run only part K of N of the jobs (K/N, 1-based)");
  cmd->add_flag("--force", o->force, "run again jobs made with other parameters");
  o->outputs.addTo(*cmd);
  o->parameters.addTo(*cmd);
  return {cmd, [o] {
            o->argv = invocation();
            return bench(*o);
          }};
}

}  // namespace camcov::cli
