// Recorded crowds (docs/scaling.md), on a seeded synthetic recording in the ETH/UCY format:
// 400 people over 10 minutes, each walking across a 40 m x 30 m square and back at about
// 1.2 m/s for 90 s (so about 60 at once), sampled every 0.4 s, with four walls.
//   Import          `camcov import ethucy` without the file writes: read obsmat.txt and
//                   map.xml, build the scene, validate it with the loader (target: < 1 s)
//   Run/<method>    8 cameras, the busiest 30 s, default parameters; real_time_factor =
//                   simulated seconds per wall second (target for paper: >= 10)
// Pin it to one core:  taskset -c 0 build/tests/bench/bench_tracks
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "batch/run_job.h"
#include "control/methods.h"
#include "import/ethucy_reader.h"
#include "import/scene_builder.h"
#include "scene/scene_loader.h"
#include "support/splitmix64.h"

namespace camcov {
namespace {

namespace fs = std::filesystem;

constexpr int kPeople = 400;
constexpr double kMinutes = 10.0;
constexpr double kStay = 90.0;  // s each person walks
constexpr double kStep = 0.4;   // s between samples

// The synthetic recording's folder (written once).
fs::path crowdFolder() {
  static const fs::path folder = [] {
    const fs::path dir = fs::temp_directory_path() / "camcov_bench_tracks";
    fs::create_directories(dir);
    std::ofstream obsmat(dir / "obsmat.txt");
    testing::SplitMix64 random{2026};
    for (int id = 1; id <= kPeople; ++id) {
      const double start = random.uniform(0.0, kMinutes * 60.0 - kStay);
      const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
      const double crossing = random.uniform(25.0, 35.0);  // s from one side to the other
      // Across the square and back, at about 1.2 m/s, for kStay seconds.
      const double ax = 20.0 - 18.0 * std::cos(angle), ay = 15.0 - 13.0 * std::sin(angle);
      const double bx = 40.0 - ax, by = 30.0 - ay;
      for (double t = 0.0; t <= kStay; t += kStep) {
        const double phase = std::fmod(t / crossing, 2.0);
        const double u = phase <= 1.0 ? phase : 2.0 - phase;
        // Frames at 25 fps, as eth_hotel's.
        obsmat << std::lround((start + t) * 25.0) << ' ' << id << ' ' << ax + (bx - ax) * u << " 0 "
               << ay + (by - ay) * u << " 0 0 0\n";
      }
    }
    std::ofstream(dir / "map.xml")
        << "<map><Line x1=\"10\" y1=\"8\" x2=\"14\" y2=\"8\"/><Line x1=\"26\" y1=\"8\" x2=\"30\" "
           "y2=\"8\"/><Line x1=\"10\" y1=\"22\" x2=\"14\" y2=\"22\"/><Line x1=\"26\" y1=\"22\" "
           "x2=\"30\" y2=\"22\"/></map>\n";
    return dir;
  }();
  return folder;
}

import::SceneOptions crowdOptions(double busiest){import::SceneOptions o;
o.cameras = 8;
o.busiest = busiest;
return o;
}  // namespace

void Import(benchmark::State& state) {
  const fs::path folder = crowdFolder();
  for (auto _ : state) {
    const import::Recording recording = import::readEthUcy(folder.string(), 25.0);
    const import::BuiltScene built = import::buildScene(recording, crowdOptions(0.0));
    benchmark::DoNotOptimize(scene::parseScene(built.scene.dump(), "crowd.json").targets.size());
  }
  state.counters["people"] = kPeople;
}

void Run(benchmark::State& state, const std::string& method) {
  const import::Recording recording = import::readEthUcy(crowdFolder().string(), 25.0);
  const scene::Scene scene = scene::parseScene(
      import::buildScene(recording, crowdOptions(30.0)).scene.dump(), "crowd.json");
  records::RunMetadata metadata;
  metadata.scene = scene.name;
  metadata.method = method;
  metadata.seed = 1;
  metadata.parameters.sim.duration = 30.0;
  int most = 0;
  for (auto _ : state) {
    const auto controller = control::requireMethod(method).make(scene, metadata.parameters, 1);
    const records::RunRecord run = batch::recordRun(scene, metadata, *controller);
    for (const auto& step : run.steps)
      most = std::max(most, step.targetsPresent);
  }
  state.counters["people_at_once"] = most;
  state.counters["real_time_factor"] = benchmark::Counter(
      30.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK(Import)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Run, paper, std::string("paper"))->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(Run, local, std::string("local"))->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace camcov
}  // namespace camcov

BENCHMARK_MAIN();
