#pragma once
// The options every command that runs the method shares: --params FILE and --set k=v.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "params/parameters.h"

namespace camcov::cli {

class ParameterOptions {
 public:
  void addTo(CLI::App& command);
  // Defaults, then the file, then each --set in order; validated. Throws InputError.
  params::Parameters resolve() const { return resolve(assignments_); }
  // The same with `assignments` for the --set (one setting of a study, params/sweep.h).
  params::Parameters resolve(const std::vector<std::string>& assignments) const;
  // The overrides as given, for the results metadata.
  const std::vector<std::string>& assignments() const { return assignments_; }

 private:
  std::string file_;
  std::vector<std::string> assignments_;
};

}  // namespace camcov::cli
