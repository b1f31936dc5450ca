// `camcov params`: the parameters a run would use, as JSON, or the documented table.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "cli/command.h"
#include "cli/parameter_options.h"
#include "params/parameter_table.h"

namespace camcov::cli {

Registration addParamsCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "params", "Print the parameters (Table I defaults, then --params, then --set) as JSON");
  auto options = std::make_shared<ParameterOptions>();
  auto describe = std::make_shared<bool>(false);
  options->addTo(*cmd);
  cmd->add_flag("--describe", *describe, "print a table: key, symbol, unit, range, meaning");
  return {cmd, [options, describe] {
            const params::Parameters p = options->resolve();
            if (!*describe) {
              std::cout << params::toJson(p).dump(2) << "\n";
              return 0;
            }
            for (const auto& f : params::parameterTable()) {
              std::cout << fmt::format("{:<29} {:<4} {:>8}  {:<10} [{}, {}]{}\n    {}\n", f.key,
                                       f.symbol, f.get(p), f.unit, f.min, f.max,
                                       f.boolean   ? " true|false"
                                       : f.integer ? " integer"
                                                   : "",
                                       f.description);
            }
            return 0;
          }};
}

}  // namespace camcov::cli
