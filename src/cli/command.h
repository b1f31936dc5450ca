#pragma once
// Each subcommand lives in its own file and registers itself on the application. The action
// runs after parsing and returns the process exit code (0 ok, 2 bad input).
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace camcov::cli {

using Action = std::function<int()>;

// Adds the subcommand to `app` and returns the action to run when it was selected.
struct Registration {
  CLI::App* command;
  Action action;
};

// The command line camcov was started with (argv), for results metadata.
const std::vector<std::string>& invocation();
void setInvocation(int argc, char** argv);

// Every command below, the version flag and the numeric options' checks, on `app`.
std::vector<Registration> addCommands(CLI::App& app);

Registration addValidateCommand(CLI::App& app);
Registration addStateCommand(CLI::App& app);
Registration addParamsCommand(CLI::App& app);
Registration addInspectCommand(CLI::App& app);
Registration addRunCommand(CLI::App& app);
Registration addRenderCommand(CLI::App& app);
Registration addVideoCommand(CLI::App& app);
Registration addBenchCommand(CLI::App& app);
Registration addMergeCommand(CLI::App& app);
Registration addReportCommand(CLI::App& app);
Registration addExploreCommand(CLI::App& app);
Registration addPlaygroundCommand(CLI::App& app);
Registration addImportCommand(CLI::App& app);
Registration addGenerateCommand(CLI::App& app);
Registration addOptimumCommand(CLI::App& app);

}  // namespace camcov::cli
