// Frames per second of the video path at 1280x720 (the target: at least 100 on one
// core): FrameBuilder (world and visibility), FrameRenderer (Cairo), VideoEncoder (colour
// conversion and libx264 with one thread).
// Replay/<scene> is what `camcov video` does per frame: the scene's paper-method run (seed 1,
// the default parameters, 30 s, simulated before timing) replayed step after step, round and
// round, each step built, drawn and encoded. Build/, Rasterize/ and Encode/dynamic9 are the
// parts, on frames whose cameras turn in place (no run needed); Convert/dynamic9/* is the
// colour conversion alone, ours and libswscale's.
// items_per_second is frames per CPU second of the whole process. Pin it to one core, and
// repeat it on a shared machine:
//   taskset -c 0 build/viz/bench/bench_viz --benchmark_repetitions=3
// Scenes come from COVERAGE_SCENES_DIR, by default ../shared/coverage_scenes beside the clone.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "batch/run_job.h"
#include "control/paper_controller.h"
#include "scene/scene_loader.h"
#include "support/bench_scenes_dir.h"
#include "viz/argb_to_yuv420.h"
#include "viz/frame.h"
#include "viz/frame_renderer.h"
#include "viz/run_replay.h"
#include "viz/video_encoder.h"

extern "C" {
#include <libswscale/swscale.h>
}

namespace camcov::viz {
namespace {

constexpr double kDt = 0.1;

// The scene's cameras at time t, turning in place at 0.3 rad/s.
std::vector<geometry::Pose> posesAt(const scene::Scene& scene, double t) {
  std::vector<geometry::Pose> poses;
  for (const auto& c : scene.cameras)
    poses.push_back({c.initial.x, c.initial.y, c.initial.yaw + 0.3 * t});
  return poses;
}

std::filesystem::path scratchVideo() {
  return std::filesystem::temp_directory_path() /
         ("bench_viz_" + std::to_string(::getpid()) + ".mp4");
}

// The paper method's run of `scene`, as `camcov run` records it.
records::RunRecord paperRun(const scene::Scene& scene) {
  records::RunMetadata metadata;
  metadata.scene = scene.name;
  metadata.method = "paper";
  metadata.seed = 1;
  control::PaperController controller(scene, metadata.parameters, metadata.seed);
  return batch::recordRun(scene, std::move(metadata), controller);
}

void replay(benchmark::State& state, const scene::Scene& scene) {
  const records::RunRecord run = paperRun(scene);
  const VideoSettings settings = runVideoSettings(run);
  RunReplay replay(run, scene);
  FrameRenderer renderer(settings.width, settings.height, FrameUse::Video);
  VideoEncoder encoder(scratchVideo(), settings);
  Frame frame;
  const std::size_t frames = replay.frameCount(settings.fps);
  std::size_t k = 0;
  for (auto _ : state) {
    replay.build(replay.stepOfFrame(k++ % frames, settings.fps), frame);
    encoder.addFrame(renderer.rasterize(frame));
  }
  state.SetItemsProcessed(state.iterations());
  // Leaving without finish() discards the file: flushing the last frames is not per-frame work.
}

// The three parts on their own, for one scene.
void build(benchmark::State& state, const scene::Scene& scene) {
  FrameBuilder builder(scene);
  Frame frame;
  double t = 0.0;
  for (auto _ : state) {
    builder.build(t, posesAt(scene, t), frame);
    t += kDt;
  }
  state.SetItemsProcessed(state.iterations());
}

void rasterize(benchmark::State& state, const scene::Scene& scene) {
  FrameBuilder builder(scene);
  FrameRenderer renderer(1280, 720, FrameUse::Video);
  Frame frame;
  builder.build(10.0, posesAt(scene, 10.0), frame);
  for (auto _ : state)
    benchmark::DoNotOptimize(renderer.rasterize(frame).pixels);
  state.SetItemsProcessed(state.iterations());
}

// 100 distinct frames of `scene` rendered beforehand (its cameras turning in place).
class RenderedFrames {
 public:
  RenderedFrames(const scene::Scene& scene, const VideoSettings& settings)
      : width_(settings.width), height_(settings.height) {
    FrameBuilder builder(scene);
    FrameRenderer renderer(settings.width, settings.height, FrameUse::Video);
    Frame frame;
    for (int k = 0; k < 100; ++k) {
      builder.build(k * kDt, posesAt(scene, k * kDt), frame);
      const RasterImage image = renderer.rasterize(frame);
      frames_.emplace_back(image.pixels, image.pixels + image.stride * image.height);
      stride_ = image.stride;
    }
  }
  // The next frame, round and round, as an image without history: all of it is converted.
  RasterImage next() { return {frames_[k_++ % frames_.size()].data(), width_, height_, stride_}; }

 private:
  std::vector<std::vector<std::uint8_t>> frames_;
  int width_, height_, stride_ = 0;
  std::size_t k_ = 0;
};

// Colour conversion and libx264: x264 codes repeated frames for free, hence distinct frames.
void encode(benchmark::State& state, const scene::Scene& scene) {
  const VideoSettings settings;
  RenderedFrames frames(scene, settings);
  VideoEncoder encoder(scratchVideo(), settings);
  for (auto _ : state)
    encoder.addFrame(frames.next());
  state.SetItemsProcessed(state.iterations());
}

// The colour conversion alone: argbToYuv420, and libswscale's conversion to the same picture
// (exact 2×2 chroma averaging, BT.709 limited range) that it replaced.
void convert(benchmark::State& state, const scene::Scene& scene, bool libswscale) {
  const VideoSettings settings;
  RenderedFrames frames(scene, settings);
  const int w = settings.width, h = settings.height;
  std::vector<std::uint8_t> y(w * h), u(w * h / 4), v(w * h / 4);
  const Yuv420Picture picture{{y.data(), u.data(), v.data()}, {w, w / 2, w / 2}};
  SwsContext* sws = nullptr;
  if (libswscale) {
    sws = sws_getContext(w, h, AV_PIX_FMT_RGB32, w, h, AV_PIX_FMT_YUV420P,
                         SWS_AREA | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr);
    sws_setColorspaceDetails(sws, sws_getCoefficients(SWS_CS_DEFAULT), 1,
                             sws_getCoefficients(SWS_CS_ITU709), 0, 0, 1 << 16, 1 << 16);
  }
  for (auto _ : state) {
    const RasterImage image = frames.next();
    if (libswscale) {
      sws_scale(sws, &image.pixels, &image.stride, 0, h, picture.planes, picture.strides);
    } else {
      argbToYuv420(image, picture);
    }
    benchmark::DoNotOptimize(y.data());
  }
  sws_freeContext(sws);  // nothing for nullptr
  state.SetItemsProcessed(state.iterations());
}

}  // namespace
}  // namespace camcov::viz

int main(int argc, char** argv) {
  using namespace camcov;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(testing::benchScenesDir())) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  const params::SimParams sim;  // the runs' defaults: 30 s at dt = 0.1 s
  const auto framesPerRun =
      static_cast<benchmark::IterationCount>(std::lround(sim.duration / sim.dt) + 1);
  for (const auto& file : files) {
    const scene::Scene s = scene::loadScene(file);  // each benchmark keeps a copy
    benchmark::RegisterBenchmark(("Replay/" + s.name).c_str(), viz::replay, s)
        ->Iterations(framesPerRun)  // each repetition, the whole run once
        ->MeasureProcessCPUTime()
        ->Unit(benchmark::kMillisecond);
    if (s.name == "dynamic9") {
      benchmark::RegisterBenchmark("Build/dynamic9", viz::build, s)->MeasureProcessCPUTime();
      benchmark::RegisterBenchmark("Rasterize/dynamic9", viz::rasterize, s)
          ->MeasureProcessCPUTime();
      benchmark::RegisterBenchmark("Encode/dynamic9", viz::encode, s)->MeasureProcessCPUTime();
      benchmark::RegisterBenchmark("Convert/dynamic9/argbToYuv420", viz::convert, s, false)
          ->MeasureProcessCPUTime();
      benchmark::RegisterBenchmark("Convert/dynamic9/libswscale", viz::convert, s, true)
          ->MeasureProcessCPUTime();
    }
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
