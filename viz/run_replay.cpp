#include "viz/run_replay.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "control/event_kind.h"
#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "viz/frame_renderer.h"

namespace camcov::viz {
namespace {

// Recorded times are sums of dt; this absorbs their rounding when comparing them.
constexpr double kTimeSlack = 1e-6;

bool startsPlan(const control::ControlEvent& e) {
  return !e.path.empty();  // "plan" and "replan" carry the path the camera now follows
}

bool endsPlan(const control::ControlEvent& e) {
  using control::EventKind;
  const auto kind = control::eventKindNamed(e.kind);
  return kind == EventKind::PlanCompleted || kind == EventKind::PlanAborted ||
         kind == EventKind::PlanFailed;
}

// The part of `path` still ahead of a camera at `position`: from it, through the waypoints
// after the leg it is closest to.
void remainingPath(std::span<const geometry::Pose> path, geometry::Vec2 position,
                   std::vector<geometry::Vec2>& out) {
  std::size_t leg = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double d =
        geometry::distanceToSegment(position, path[i].position(), path[i + 1].position());
    if (d < best) {
      best = d;
      leg = i;
    }
  }
  out.assign(1, position);
  for (std::size_t i = std::min(leg + 1, path.size() - 1); i < path.size(); ++i) {
    out.push_back(path[i].position());
  }
}

}  // namespace

RunScene loadRunScene(const records::RunMetadata& metadata, const std::filesystem::path& moved) {
  const std::filesystem::path file =
      moved.empty() ? std::filesystem::path(metadata.sceneFile) : moved;
  if (moved.empty() && !std::filesystem::exists(file)) {
    throw InputError(fmt::format("the run's scene file {} is not there; give it with --scene",
                                 metadata.sceneFile));
  }
  scene::SceneFile s = scene::loadSceneFile(file);
  return {std::move(s.scene), s.hash != metadata.sceneHash};
}

VideoSettings runVideoSettings(const records::RunRecord& run) {
  VideoSettings settings;
  settings.fps = std::max(1, static_cast<int>(std::lround(1.0 / run.metadata.parameters.sim.dt)));
  return settings;
}

RunReplay::RunReplay(const records::RunRecord& run, const scene::Scene& scene)
    : run_(run),
      builder_(scene),
      subtitle_(fmt::format("method {}, seed {}", run.metadata.method, run.metadata.seed)),
      plans_(scene.cameras.size()) {
  if (run.steps.empty()) throw InputError("the run has no recorded steps");
  for (const auto& step : run.steps) {
    if (step.cameras.size() != scene.cameras.size()) {
      throw InputError(fmt::format("the run has {} cameras at t = {} s, the scene {}",
                                   step.cameras.size(), step.time, scene.cameras.size()));
    }
  }
  for (const auto& e : run.events) {
    if (e.camera < 0 || static_cast<std::size_t>(e.camera) >= plans_.size()) continue;
    auto& spans = plans_[static_cast<std::size_t>(e.camera)];
    const bool open = !spans.empty() && std::isinf(spans.back().end);
    if (open && (startsPlan(e) || endsPlan(e))) spans.back().end = e.time;
    if (startsPlan(e)) spans.push_back({e.time, std::numeric_limits<double>::infinity(), e.path});
  }
}

std::size_t RunReplay::frameCount(int fps) const {
  const double span = run_.steps.back().time - run_.steps.front().time;
  return static_cast<std::size_t>(std::floor(span * fps + kTimeSlack)) + 1;
}

std::size_t RunReplay::stepOfFrame(std::size_t frame, int fps) const {
  const double t = run_.steps.front().time + static_cast<double>(frame) / fps;
  const auto& steps = run_.steps;
  const auto after =
      std::lower_bound(steps.begin(), steps.end(), t,
                       [](const auto& step, double time) { return step.time < time; });
  if (after == steps.end()) return steps.size() - 1;
  if (after == steps.begin()) return 0;
  const auto before = std::prev(after);
  return static_cast<std::size_t>((t - before->time <= after->time - t ? before : after) -
                                  steps.begin());
}

const RunReplay::PlanSpan* RunReplay::planAt(std::size_t camera, double time) const {
  for (const PlanSpan& span : plans_[camera]) {
    if (span.start <= time + kTimeSlack && time + kTimeSlack < span.end) return &span;
  }
  return nullptr;
}

void RunReplay::build(std::size_t step, Frame& out) {
  const records::StepRow& row = run_.steps.at(step);
  builder_.build(row.time, row.cameras, out);
  out.caption.subtitle = subtitle_;
  for (std::size_t j = 0; j < out.cameras.size(); ++j) {
    CameraView& c = out.cameras[j];
    if (j < row.goals.size()) c.goal = row.goals[j];
    if (const PlanSpan* plan = planAt(j, row.time)) {
      remainingPath(plan->path, c.pose.position(), c.plan);
    }
  }
}

std::size_t writeRunVideo(const records::RunRecord& run, const scene::Scene& scene,
                          const std::filesystem::path& file, const VideoSettings& settings) {
  RunReplay replay(run, scene);
  FrameRenderer renderer(settings.width, settings.height, FrameUse::Video);
  VideoEncoder encoder(file, settings);
  Frame frame;
  RasterImage image;
  std::size_t shown = run.steps.size();  // none yet
  const std::size_t frames = replay.frameCount(settings.fps);
  for (std::size_t k = 0; k < frames; ++k) {
    // Above the recorded rate a step is held for several frames: drawn once, encoded again.
    const std::size_t step = replay.stepOfFrame(k, settings.fps);
    if (step != shown) {
      replay.build(step, frame);
      image = renderer.rasterize(frame);
      shown = step;
    }
    encoder.addFrame(image);
  }
  encoder.finish();
  return frames;
}

}  // namespace camcov::viz
