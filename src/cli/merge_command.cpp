// `camcov merge DIR... --out DIR`: combine the results folders of shards (or of separate
// machines) into one, then write the summary and logs as `camcov bench` would.
#include "bench/run_bench.h"
#include "cli/bench_output_options.h"
#include "cli/command.h"
#include "cli/terminal_observer.h"

namespace camcov::cli {

Registration addMergeCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "merge", "Combine bench folders (shards, machines) into one; write summary and logs");
  struct Options {
    std::vector<std::string> inputs;
    std::string out;
    bench::BenchOutputOptions outputs;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("folders", o->inputs, "bench --out folders to combine")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out,-o", o->out, "the combined folder (may be one of the inputs)")->required();
  addBenchOutputOptions(*cmd, o->outputs);
  return {cmd, [o] {
            TerminalObserver terminal;
            const bench::BenchResult result =
                bench::mergeBench(o->inputs, o->out, o->outputs, invocation(), terminal);
            return result.failedJobs > 0 ? 1 : 0;
          }};
}

}  // namespace camcov::cli
