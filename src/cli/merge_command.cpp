// `camcov merge DIR... --out DIR`: combine the results folders of shards (or of separate
// machines) into one, then write the summary and logs as `camcov bench` would.
#include <algorithm>
#include <memory>
#include <thread>

#include "batch/merge.h"
#include "cli/bench_outputs.h"
#include "cli/command.h"
#include "records/atomic_file.h"

namespace camcov::cli {
namespace {

struct MergeOptions {
  std::vector<std::string> inputs;
  std::string out;
  BenchOutputOptions outputs;
};

int merge(const MergeOptions& o) {
  o.outputs.check();  // a bad --videos or --explorer fails before anything is copied
  const records::BatchFolder target(o.out);
  records::NewFolderGuard created(target.root());
  const records::BatchManifest manifest = batch::mergeFolders(o.inputs, target, invocation());
  const int status = writeBenchOutputs(target, manifest, target.allJobs(), o.outputs,
                                       std::max(1u, std::thread::hardware_concurrency()));
  created.keep();
  return status;
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
