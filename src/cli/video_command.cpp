// `camcov video RESULTS_FILE -o run.mp4 [--fps N] [--width W --height H] [--scene FILE]`: a
// recorded run (its results JSON) replayed as an H.264 MP4 that plays in a browser.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/command.h"
#include "cli/number_options.h"
#include "records/run_files.h"
#include "util/input_error.h"
#include "util/protected_files.h"
#include "viz/run_replay.h"
#include "viz/video_encoder.h"

namespace camcov::cli {
namespace {

struct VideoOptions {
  std::string results;
  std::string out;
  std::string scene;
  int fps = 0;  // 0: one frame per recorded step
  int width = 1280;
  int height = 720;
};

int video(const VideoOptions& o) {
  viz::requireMp4(o.out);
  if (o.width % 2 != 0 || o.height % 2 != 0) {
    throw InputError(
        fmt::format("--width {} --height {}: H.264 (yuv420p) needs even sizes", o.width, o.height));
  }
  ProtectedFiles::protect(o.results);  // the video never replaces the run it shows
  const records::RunRecord run = records::loadRunFile(o.results);
  const viz::RunScene scene = viz::loadRunScene(run.metadata, o.scene);
  if (scene.changed) {
    std::cerr << "warning: the scene file has changed since the run; the video shows the scene "
                 "as it is now\n";
  }
  viz::VideoSettings settings = viz::runVideoSettings(run);
  settings.width = o.width;
  settings.height = o.height;
  if (o.fps > 0) settings.fps = o.fps;
  const std::size_t frames = viz::writeRunVideo(run, scene.scene, o.out, settings);
  std::cout << fmt::format("{} {} seed {}: {} frames at {} fps\n  -> {}\n", run.metadata.scene,
                           run.metadata.method, run.metadata.seed, frames, settings.fps, o.out);
  return 0;
}

}  // namespace

Registration addVideoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("video", "Replay a recorded run as an H.264 MP4 video");
  auto o = std::make_shared<VideoOptions>();
  cmd->add_option("results", o->results, "results file of a run (JSON, from camcov run)")
      ->required();
  cmd->add_option("--out,-o", o->out, "video file (.mp4)")->required();
  cmd->add_option("--fps", o->fps,
                  "frames per second (default: one frame per recorded step, 10 for dt = 0.1 s); "
                  "steps are held or skipped to match")
      ->check(within(1, 240));
  cmd->add_option("--width", o->width, "frame width, px (even)")
      ->check(within(16, 8192))
      ->capture_default_str();
  cmd->add_option("--height", o->height, "frame height, px (even)")
      ->check(within(16, 8192))
      ->capture_default_str();
  cmd->add_option("--scene", o->scene,
                  "scene file, if it is no longer where the run's metadata says");
  return {cmd, [o] { return video(*o); }};
}

}  // namespace camcov::cli
