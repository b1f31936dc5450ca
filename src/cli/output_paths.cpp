#include "cli/output_paths.h"

#include <string>

namespace camcov::cli {

void refuseEmptyOutputPaths(CLI::App& app) {
  const CLI::Validator notEmpty(
      [](std::string& text) -> std::string {
        return text.empty() ? "is empty: name the file or folder to write" : "";
      },
      "", "not empty");
  for (CLI::Option* option : app.get_options()) {
    if (option->check_lname("out")) option->check(notEmpty);
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    refuseEmptyOutputPaths(*sub);
}

}  // namespace camcov::cli
