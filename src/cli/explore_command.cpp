// `camcov explore RUN.json... -o run.html [--scene FILE]`: the run explorer, one
// offline HTML page replaying runs of one scene side by side (reports/explorer).
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/command.h"
#include "reports/explorer/explorer_page.h"
#include "util/input_error.h"
#include "util/protected_files.h"

namespace camcov::cli {
namespace {

struct ExploreOptions {
  std::vector<std::string> runs;
  std::string out;
  std::string scene;       // if the runs' scene file has moved
  std::string playground;  // a playground page of the scene, to link each step to
};

int explore(const ExploreOptions& o) {
  if (std::filesystem::path(o.out).extension() != ".html") {
    throw InputError(o.out + ": the explorer is an HTML page; name it *.html");
  }
  for (const std::string& run : o.runs)
    ProtectedFiles::protect(run);  // the page never replaces a run it shows
  reports::explorer::writeExplorer({o.runs.begin(), o.runs.end()}, o.out, o.scene, o.playground);
  std::cout << fmt::format("wrote {}\n", o.out);
  return 0;
}

}  // namespace

Registration addExploreCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "explore",
      "Write the run explorer: one offline HTML page that replays runs of one scene side by "
      "side, with a timeline, each edge's visibleBy and why other cameras miss it");
  auto o = std::make_shared<ExploreOptions>();
  cmd->add_option("runs", o->runs,
                  "results files of runs of one scene (JSON, from camcov run "
                  "or a bench folder's runs/)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", o->out, "the page (.html)")->required();
  cmd->add_option("--scene", o->scene,
                  "scene file, if it is no longer where the runs' metadata says");
  cmd->add_option("--playground", o->playground,
                  "a page of `camcov playground` for the scene: each step links to it, at the "
                  "step's time and camera poses")
      ->check(CLI::ExistingFile);
  return {cmd, [o] { return explore(*o); }};
}

}  // namespace camcov::cli
