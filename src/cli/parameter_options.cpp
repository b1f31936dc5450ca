#include "cli/parameter_options.h"

#include <iostream>

#include "params/parameter_table.h"

namespace camcov::cli {

void ParameterOptions::addTo(CLI::App& command) {
  command.add_option("--params", file_, "JSON file of parameters (see `camcov params`)")
      ->check(CLI::ExistingFile);
  command
      .add_option("--set", assignments_,
                  "override one parameter, e.g. --set global.K=200 (bench: a list, "
                  "--set comms.range=5,10,inf, makes a study, one batch per value)")
      ->type_name("KEY=VALUE");
}

params::Parameters ParameterOptions::resolve(const std::vector<std::string>& assignments) const {
  params::Parameters p = file_.empty() ? params::Parameters{} : params::loadParameters(file_);
  for (const auto& a : assignments)
    params::applyAssignment(p, a);
  params::validate(p);
  for (const auto& w : params::warnings(p))
    std::cerr << "warning: " << w << "\n";
  return p;
}

}  // namespace camcov::cli
