// camcov: the one place that wires the stages together. Exit codes: 0 success, 1 internal
// error, 2 bad input (scene, parameters, command line).
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cli/command.h"
#include "cli/signal_cleanup.h"
#include "cli/terminal_safe_stream.h"
#include "util/input_error.h"

int main(int argc, char** argv) {
  using namespace camcov;
  const cli::TerminalSafeStderr safeMessages;
  cli::removeTemporaryOutputsOnSignal();
  CLI::App app{"camcov: dynamic multi-target coverage with robotic cameras (Hönig & Ayanian)"};
  const std::vector<cli::Registration> commands = cli::addCommands(app);
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
