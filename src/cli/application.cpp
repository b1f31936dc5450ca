// The application's commands, registered in the order `camcov --help` lists them; shared by
// main() and the command-line fuzzer, so both parse exactly what a person can type.
#include "camcov/version.h"
#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/output_paths.h"

namespace camcov::cli {
namespace {
std::vector<std::string> commandLine;
}  // namespace

const std::vector<std::string>& invocation() {
  return commandLine;
}

void setInvocation(int argc, char** argv) {
  commandLine.assign(argv, argv + argc);
}

std::vector<Registration> addCommands(CLI::App& app) {
  app.set_version_flag("--version", std::string("camcov ") + kVersion);
  app.require_subcommand(1);
  std::vector<Registration> commands{
      addValidateCommand(app), addStateCommand(app),    addParamsCommand(app),
      addInspectCommand(app),  addRunCommand(app),      addRenderCommand(app),
      addVideoCommand(app),    addBenchCommand(app),    addMergeCommand(app),
      addReportCommand(app),   addExploreCommand(app),  addPlaygroundCommand(app),
      addImportCommand(app),   addGenerateCommand(app), addOptimumCommand(app),
  };
  guardNumericOptions(app);
  refuseEmptyOutputPaths(app);
  return commands;
}

}  // namespace camcov::cli
