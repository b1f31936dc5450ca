#pragma once
// A recorded run as frames and as a video (SPEC section 6). A results file holds, per step,
// the cameras' poses and goals, and the plan events with their paths, but no geometry: per
// step the world at its time is recomputed from the scene, and visibility with it, as the
// simulator saw it.
#include <cstddef>
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "records/run_record.h"
#include "scene/scene.h"
#include "viz/frame.h"
#include "viz/video_encoder.h"

namespace camcov::viz {

struct RunScene {
  scene::Scene scene;
  bool changed = false;  // the file's bytes differ from those the run was made with
};

// The scene a run was made with: the file named in its metadata, or `moved` if given (the
// file has moved since). InputError if it is missing (saying to give --scene) or invalid.
RunScene loadRunScene(const records::RunMetadata& metadata,
                      const std::filesystem::path& moved = {});

// The default settings with one frame per recorded step: fps = 1 / dt, rounded, at least 1.
VideoSettings runVideoSettings(const records::RunRecord& run);

class RunReplay {
 public:
  // Keeps a reference to `run`. InputError if the run has no steps or a step's camera count
  // differs from the scene's.
  RunReplay(const records::RunRecord& run, const scene::Scene& scene);

  // Frames at `fps` span the run from its first to its last step; frame k shows the step
  // recorded nearest to k / fps after the first (so each step once when fps = 1 / dt, each
  // step held for several frames at a higher rate, steps skipped at a lower one).
  std::size_t frameCount(int fps) const;
  std::size_t stepOfFrame(std::size_t frame, int fps) const;

  // The frame of recorded step `step`: the world, visibility and numbers at its time, each
  // camera's goal, and the rest of the plan it follows.
  void build(std::size_t step, Frame& out);

 private:
  // A camera follows `path` from `start` until it is completed, aborted or replaced.
  struct PlanSpan {
    double start = 0.0;
    double end = std::numeric_limits<double>::infinity();
    std::span<const geometry::Pose> path;
  };
  const PlanSpan* planAt(std::size_t camera, double time) const;

  const records::RunRecord& run_;
  FrameBuilder builder_;
  std::string subtitle_;
  std::vector<std::vector<PlanSpan>> plans_;  // per camera, in time order
};

// Renders every frame of the run at settings.fps and encodes them into `file`; returns the
// number of frames.
std::size_t writeRunVideo(const records::RunRecord& run, const scene::Scene& scene,
                          const std::filesystem::path& file, const VideoSettings& settings);

}  // namespace camcov::viz
