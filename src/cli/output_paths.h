#pragma once
// Every command's --out names a file or folder to write: an empty one would mean the working
// folder itself (`bench --out ''` writing a whole batch beside whatever is there), never what a
// person meant. One check for every --out of the application, so an output added later has it.
#include <CLI/CLI.hpp>

namespace camcov::cli {

// Adds the check to the --out option of `app` and of its subcommands, recursively. Call it once,
// after every command has registered its options.
void refuseEmptyOutputPaths(CLI::App& app);

}  // namespace camcov::cli
