#pragma once
// Each subcommand lives in its own file and registers itself on the application. The action
// runs after parsing and returns the process exit code (0 ok, 2 bad input).
#include <CLI/CLI.hpp>
#include <functional>
#include <vector>

namespace camcov::cli {

using Action = std::function<int()>;

// Adds the subcommand to `app` and returns the action to run when it was selected.
struct Registration {
  CLI::App* command;
  Action action;
};

Registration addValidateCommand(CLI::App& app);
Registration addStateCommand(CLI::App& app);
Registration addParamsCommand(CLI::App& app);

}  // namespace camcov::cli
