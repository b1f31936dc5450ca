// camcov: the one place that wires the stages together. Exit codes: 0 success, 1 internal
// error, 2 bad input (scene, parameters, command line).
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "camcov/version.h"
#include "cli/command.h"
#include "cli/number_options.h"
#include "util/input_error.h"

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
}  // namespace camcov::cli

int main(int argc, char** argv) {
  using namespace camcov;
  CLI::App app{"camcov: dynamic multi-target coverage with robotic cameras (Hönig & Ayanian)"};
  app.set_version_flag("--version", std::string("camcov ") + kVersion);
  app.require_subcommand(1);
  const std::vector<cli::Registration> commands{
      cli::addValidateCommand(app), cli::addStateCommand(app),   cli::addParamsCommand(app),
      cli::addInspectCommand(app),  cli::addRunCommand(app),     cli::addRenderCommand(app),
      cli::addVideoCommand(app),    cli::addBenchCommand(app),   cli::addMergeCommand(app),
      cli::addReportCommand(app),   cli::addExploreCommand(app), cli::addImportCommand(app),
      cli::addGenerateCommand(app), cli::addOptimumCommand(app),
  };
  cli::guardNumericOptions(app);
  cli::setInvocation(argc, argv);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  }
  try {
    for (const auto& c : commands) {
      if (c.command->parsed()) return c.action();
    }
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << "\n";
    return 1;
  }
  return 1;
}
