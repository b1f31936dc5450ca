// What the safety layer costs (issue: at most 5 % of a dynamic9 run):
//   Run/<scene>/<method>/<layer on|off>  a whole 30 s run, seed 1, default parameters, as
//                                        `camcov run` simulates it (no files written)
//   Layer/<scene>                        SafetyFilter::apply, every step of that paper run
//   Accounting/<scene>                   StepAccounting::measure, every step of that run
// The last two are per step (items_per_second = steps per second); together they are what
// the layer adds to a step, and "off" still pays both (the layer judges and the simulator
// accounts in continuous time whether or not commands are changed). Pin it to one core:
//   COVERAGE_SCENES_DIR=../shared/coverage_scenes taskset -c 0 build/tests/bench/bench_safety
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "batch/run_job.h"
#include "control/methods.h"
#include "kinematics/kinematics.h"
#include "safety/safety_filter.h"
#include "safety/step_contacts.h"
#include "scene/scene_loader.h"
#include "support/bench_scenes_dir.h"

namespace camcov::safety {
namespace {

records::RunRecord record(const scene::Scene& scene, const std::string& method, bool layer) {
  records::RunMetadata metadata;
  metadata.scene = scene.name;
  metadata.method = method;
  metadata.seed = 1;
  metadata.parameters.safety.enabled = layer;
  const auto controller = control::requireMethod(method).make(scene, metadata.parameters, 1);
  return batch::recordRun(scene, metadata, *controller);
}

void run(benchmark::State& state, const scene::Scene& scene, const std::string& method,
         bool layer) {
  for (auto _ : state)
    benchmark::DoNotOptimize(record(scene, method, layer).summary.averageCoverage);
}

void layer(benchmark::State& state, const scene::Scene& scene) {
  const records::RunRecord r = record(scene, "paper", true);
  const kinematics::Kinematics kinematics(scene);
  std::vector<kinematics::World> worlds;
  for (const auto& step : r.steps)
    worlds.push_back(kinematics.worldAt(step.time));
  params::Parameters p;
  std::vector<geometry::Vec2> velocities;
  for (auto _ : state) {
    SafetyFilter filter(scene, p);
    for (std::size_t k = 0; k + 1 < r.steps.size(); ++k) {
      // The velocity the run took, as the command: the common case, nothing to change.
      velocities.clear();
      for (std::size_t j = 0; j < r.steps[k].cameras.size(); ++j)
        velocities.push_back(
            (r.steps[k + 1].cameras[j].position() - r.steps[k].cameras[j].position()) / p.sim.dt);
      filter.apply(worlds[k], r.steps[k].cameras, velocities);
      benchmark::DoNotOptimize(velocities.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(r.steps.size() - 1));
}

void accounting(benchmark::State& state, const scene::Scene& scene) {
  const records::RunRecord r = record(scene, "paper", true);
  const kinematics::Kinematics kinematics(scene);
  const StepAccounting accounting(kinematics, params::Parameters{}.sim.delta);
  std::vector<kinematics::World> worlds;
  for (const auto& step : r.steps)
    worlds.push_back(kinematics.worldAt(step.time));
  for (auto _ : state) {
    // As the simulator does: one sample per instant, each step measured between two.
    Sample before = accounting.sample(worlds[0], r.steps[0].cameras);
    for (std::size_t k = 0; k + 1 < r.steps.size(); ++k) {
      Sample after = accounting.sample(worlds[k + 1], r.steps[k + 1].cameras);
      benchmark::DoNotOptimize(accounting.measure(before, after).minObjectDistance);
      before = std::move(after);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(r.steps.size() - 1));
}

}  // namespace
}  // namespace camcov::safety

int main(int argc, char** argv) {
  using namespace camcov;
  for (const std::string name : {"dynamic9", "dynamic13", "static1"}) {
    const scene::Scene s = scene::loadScene(testing::benchScenesDir() / (name + ".json"));
    for (const std::string method : {"paper", "local"}) {
      for (const bool on : {true, false}) {
        benchmark::RegisterBenchmark(
            ("Run/" + name + "/" + method + "/" + (on ? "on" : "off")).c_str(), safety::run, s,
            method, on)
            ->Unit(benchmark::kMillisecond);
      }
    }
    benchmark::RegisterBenchmark(("Layer/" + name).c_str(), safety::layer, s)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("Accounting/" + name).c_str(), safety::accounting, s)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
