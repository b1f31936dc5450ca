// `camcov playground SCENE [--time T] [--cameras poses.json] -o page.html`: the visibility
// playground, one offline HTML page where the engine compiled to WebAssembly recomputes the
// picture at every drag (reports/playground).
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/command.h"
#include "cli/number_options.h"
#include "reports/playground/playground_page.h"
#include "scene/scene.h"
#include "util/input_error.h"
#include "util/protected_files.h"

namespace camcov::cli {
namespace {

struct PlaygroundOptions {
  std::string scene;
  double time = 0.0;
  std::string cameras;
  std::string out;
  std::string engine = CAMCOV_WASM_ENGINE_PATH;  // where this build writes it
};

int playground(const PlaygroundOptions& o) {
  if (std::filesystem::path(o.out).extension() != ".html")
    throw InputError(o.out + ": the playground is an HTML page; name it *.html");
  ProtectedFiles::protect(o.scene);  // the page never replaces the scene it shows
  if (!o.cameras.empty()) ProtectedFiles::protect(o.cameras);
  reports::playground::writePlayground(
      o.scene, o.time,
      o.cameras.empty() ? std::nullopt : std::optional<std::filesystem::path>(o.cameras), o.engine,
      o.out);
  std::cout << fmt::format("wrote {}\n", o.out);
  return 0;
}

}  // namespace

Registration addPlaygroundCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "playground",
      "Write the visibility playground: one offline HTML page with the engine compiled to "
      "WebAssembly, where cameras, vertices and time are dragged and everything is recomputed");
  auto o = std::make_shared<PlaygroundOptions>();
  cmd->add_option("scene", o->scene, "scene file (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--time,-t", o->time, "time t in seconds to start at")
      ->check(within(0.0, scene::kMaxDuration))
      ->capture_default_str();
  cmd->add_option("--cameras", o->cameras,
                  "camera poses instead of the scene's: JSON list [{\"x\":..,\"y\":..,"
                  "\"yaw_deg\":..}], one per camera")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", o->out, "the page (.html)")->required();
  cmd->add_option("--engine", o->engine, "the engine, camcov_engine.js (default: this build's)")
      ->capture_default_str();
  return {cmd, [o] { return playground(*o); }};
}

}  // namespace camcov::cli
