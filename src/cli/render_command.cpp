// `camcov render SCENE --time T [--cameras FILE] [--width W --height H] -o FILE`: one frame of
// a scene at time t, PNG or SVG by the file's extension, with the cameras at the scene's
// initial poses or at poses from a file.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/command.h"
#include "cli/number_options.h"
#include "scene/camera_poses_file.h"
#include "scene/scene_loader.h"
#include "viz/frame.h"
#include "viz/frame_renderer.h"

namespace camcov::cli {
namespace {

struct RenderOptions {
  std::string scene;
  double time = 0.0;
  std::string camerasFile;
  int width = 1280;
  int height = 720;
  std::string out;
};

int render(const RenderOptions& o) {
  viz::imageFormatOf(o.out);  // a wrong extension fails before any work
  const scene::Scene s = scene::loadScene(o.scene);
  const std::vector<geometry::Pose> cameras =
      o.camerasFile.empty() ? scene::initialPoses(s) : scene::loadCameraPosesFor(o.camerasFile, s);
  viz::FrameBuilder builder(s);
  viz::Frame frame;
  builder.build(o.time, cameras, frame);
  frame.caption.subtitle =
      o.camerasFile.empty()
          ? "cameras at their initial poses"
          : "cameras from " + std::filesystem::path(o.camerasFile).filename().string();
  viz::FrameRenderer(o.width, o.height).write(frame, o.out);
  std::cout << fmt::format("{} at t = {} s: coverage {:.4f}, utilization {:.4f}\n  -> {}\n", s.name,
                           o.time, frame.caption.coverage, frame.caption.utilization, o.out);
  return 0;
}

}  // namespace

Registration addRenderCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "render", "Draw one frame of a scene at time t: visibility, views, paths (PNG or SVG)");
  auto o = std::make_shared<RenderOptions>();
  cmd->add_option("scene", o->scene, "scene file (JSON)")->required();
  cmd->add_option("--time,-t", o->time, "time t in seconds")->check(within(0.0, 1e9));
  cmd->add_option("--cameras", o->camerasFile,
                  "JSON list of poses [{\"x\":..,\"y\":..,\"yaw_deg\":..}] (default: the scene's "
                  "initial cameras)");
  cmd->add_option("--width", o->width, "frame width, px")
      ->check(within(16, 8192))
      ->capture_default_str();
  cmd->add_option("--height", o->height, "frame height, px")
      ->check(within(16, 8192))
      ->capture_default_str();
  cmd->add_option("--out,-o", o->out, "image file: .png or .svg")->required();
  return {cmd, [o] { return render(*o); }};
}

}  // namespace camcov::cli
