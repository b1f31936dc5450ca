// `camcov merge DIR... --out DIR`: combine the results folders of shards (or of separate
// machines) into one, then write the summary and logs as `camcov bench` would.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <thread>

#include "cli/bench_outputs.h"
#include "cli/command.h"
#include "params/parameter_table.h"
#include "records/atomic_file.h"
#include "util/input_error.h"

namespace camcov::cli {
namespace {

namespace fs = std::filesystem;

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string out;
  BenchOutputOptions outputs;
};

int merge(const MergeOptions& o) {
  o.outputs.videoChoice();  // a bad --videos fails before anything is copied
  const records::BatchFolder target(o.out);
  std::optional<records::BatchManifest> manifest;
  std::map<std::string, records::JobTiming> timings;
  for (const auto& input : o.inputs) {
    const records::BatchFolder source(input);
    const auto m = source.readManifest();
    if (!m) throw InputError(input + ": not a camcov bench folder (no batch.json)");
    if (!manifest) {
      manifest = m;
    } else {
      if (params::toJson(m->parameters) != params::toJson(manifest->parameters)) {
        throw InputError(input + ": made with other parameters than " + o.inputs.front());
      }
      for (const auto& scene : m->scenes) {
        const bool known = std::any_of(manifest->scenes.begin(), manifest->scenes.end(),
                                       [&](const auto& s) { return s.name == scene.name; });
        if (!known) manifest->scenes.push_back(scene);
      }
    }
    for (const auto& [stem, t] : source.readTimings())
      timings[stem] = t;
    if (fs::exists(target.runsDir()) && fs::equivalent(source.runsDir(), target.runsDir()))
      continue;
    // Each file whole or not at all, and a run's JSON after its CSV: a run counts as finished
    // when its JSON exists, so a killed merge resumes like a killed batch.
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(source.runsDir())) {
      if (!records::isTemporaryFile(entry.path())) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) {
      return std::pair(a.extension() == ".json", a) < std::pair(b.extension() == ".json", b);
    });
    for (const fs::path& file : files)
      records::copyFileAtomically(file, target.runsDir() / file.filename());
  }
  manifest->command = invocation();
  target.writeManifest(*manifest);
  target.writeTimings(timings);
  return writeBenchOutputs(target, *manifest, target.allJobs(), o.outputs,
                           std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace

Registration addMergeCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "merge", "Combine bench folders (shards, machines) into one; write summary and logs");
  auto o = std::make_shared<MergeOptions>();
  cmd->add_option("folders", o->inputs, "bench --out folders to combine")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out,-o", o->out, "the combined folder (may be one of the inputs)")->required();
  o->outputs.addTo(*cmd);
  return {cmd, [o] { return merge(*o); }};
}

}  // namespace camcov::cli
