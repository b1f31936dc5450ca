// `camcov run SCENE --method paper|local --seed N [--duration S] [--out DIR] [--threads T]`:
// one run, its results files written atomically, its averages printed.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "batch/run_job.h"
#include "cli/command.h"
#include "cli/number_options.h"
#include "cli/parameter_options.h"
#include "control/methods.h"
#include "records/run_files.h"
#include "sim/scene_parameters.h"
#include "util/readable_number.h"
#include "util/run_threads.h"
#include "viz/run_replay.h"

namespace camcov::cli {
namespace {

struct RunOptions {
  std::string scene;
  std::string method = "paper";
  std::uint64_t seed = 1;
  double duration = -1.0;
  std::string out = "results";
  std::string video;     // also write the run's video here, if given
  unsigned threads = 0;  // 0: every core it may run on
  ParameterOptions parameters;
};

int run(const RunOptions& o) {
  control::requireMethod(o.method);
  if (!o.video.empty()) viz::requireMp4(o.video);  // before the run, not after
  // The scene read once: for its own settings, the run and the video.
  batch::JobSpec job{
      o.scene, o.method, o.seed, o.parameters.resolve(), nullptr, batch::readSceneFile(o.scene)};
  if (o.duration >= 0.0) job.parameters.sim.duration = o.duration;
  job.parameters = sim::forScene(job.parameters, job.scene->scene, o.scene, o.duration >= 0.0);
  setRunThreads(o.threads == 0 ? availableCores() : o.threads);
  const records::RunRecord record = batch::runJob(job);
  const auto file = records::writeRunFiles(record, o.out);
  const auto& s = record.summary;
  std::cout << fmt::format(
      "{} {} seed {}: average coverage {:.4f}, utilization {:.4f} over {} s; min distance to "
      "objects {:.3f} m; closer than δ {:.2f} s avoidable, {:.2f} s unavoidable\n  -> {}\n",
      record.metadata.scene, o.method, o.seed, s.averageCoverage, s.averageUtilization,
      roundedNumber(s.duration), s.minObjectDistance, s.avoidableContactTime,
      s.unavoidableContactTime, file.string());
  if (s.averageWeightedCoverage) {
    std::cout << fmt::format(
        "  average weighted coverage {:.4f} (the reward's{})\n", *s.averageWeightedCoverage,
        job.parameters.reward.weighted ? "" : " is plain: reward.weighted=false");
  }
  if (s.averageResolutionCoverage) {
    std::cout << fmt::format(
        "  average resolution coverage {:.4f} (boundary seen with enough "
        "pixels: the scene's resolution)\n",
        *s.averageResolutionCoverage);
  }
  if (!o.video.empty()) {
    viz::writeRunVideo(record, job.scene->scene, o.video, viz::runVideoSettings(record));
    std::cout << "  -> " << o.video << "\n";
  }
  return 0;
}

}  // namespace

Registration addRunCommand(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("run", "Simulate one scene with one method and seed; write its results");
  auto o = std::make_shared<RunOptions>();
  cmd->add_option("scene", o->scene, "scene file (JSON)")->required();
  std::string names;
  for (const control::Method& m : control::methods())
    names += fmt::format("{}{} ({})", names.empty() ? "" : ", ", m.name, m.description);
  cmd->add_option("--method,-m", o->method, "one of: " + names)->capture_default_str();
  cmd->add_option("--seed,-s", o->seed, "random seed of the run")->capture_default_str();
  cmd->add_option("--duration", o->duration,
                  "simulated seconds (default: the scene's own duration if it has one, else "
                  "sim.duration, 30 s)")
      ->check(within(0.0, scene::kMaxDuration, false));
  cmd->add_option("--out,-o", o->out, "folder for the results files")->capture_default_str();
  cmd->add_option("--video", o->video, "also write the run's video (MP4, 1280x720)");
  cmd->add_option("--threads,-t", o->threads,
                  "threads for the run's own work, the same results with any number (default 0: "
                  "every core it may run on)")
      ->check(within(0, 256))
      ->capture_default_str();
  o->parameters.addTo(*cmd);
  return {cmd, [o] { return run(*o); }};
}

}  // namespace camcov::cli
