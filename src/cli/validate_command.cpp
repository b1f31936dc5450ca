// `camcov validate FILE...`: one line per scene file, exit 2 if any is bad.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cli/command.h"
#include "kinematics/object_overlaps.h"
#include "params/parameters.h"
#include "scene/scene_loader.h"
#include "sim/scene_parameters.h"
#include "util/input_error.h"
#include "util/printable.h"
#include "util/readable_number.h"

namespace camcov::cli {

Registration addValidateCommand(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("validate", "Check scene files; one line per file, exit 2 if any is bad");
  auto files = std::make_shared<std::vector<std::string>>();
  cmd->add_option("files", *files, "scene files (JSON)")->required();
  return {cmd, [files] {
            int exitCode = 0;
            for (const auto& file : *files) {
              try {
                const scene::Scene s = scene::loadScene(file);
                // Checks its knowledge settings, and gives the length of its run: the scene's
                // own duration (a recording's window) where it has one.
                const params::SimParams run = sim::forScene({}, s, file, false).sim;
                std::cout << fmt::format("ok    {}: {} target(s), {} obstacle(s), {} camera(s)\n",
                                         printable(file), s.targets.size(), s.obstacles.size(),
                                         s.cameras.size());
                for (const std::string& warning : s.warnings)
                  std::cout << fmt::format("  warning: {}\n", printable(warning));
                // Over the run `camcov run` would make, at the simulator's step.
                for (const auto& o : kinematics::findObjectOverlaps(s, run.duration, run.dt)) {
                  std::cout << fmt::format("  warning: {} (checked every {} s over {} s)\n",
                                           kinematics::describeOverlap(o), roundedNumber(run.dt),
                                           roundedNumber(run.duration));
                }
              } catch (const InputError& e) {
                // On stdout, past std::cerr's filter: quoted file text made printable here.
                std::cout << "error " << printable(e.what(), {.keepLines = true}) << "\n";
                exitCode = 2;
              }
            }
            return exitCode;
          }};
}

}  // namespace camcov::cli
