// The reward's calls as the optimizers make them (docs/scaling.md), at t = 0 of a scene:
//   Sweep/<scene>        one camera's sweep (Algorithm 1) at a pose not seen before
//   Probe/<scene>        RewardModel::reward() of the whole team with one camera moved: a
//                        global-optimization sample (Algorithm 2 line 10) or a local
//                        optimizer's probe (section V-E)
//   Evaluate/<scene>     RewardModel::evaluate() of the whole team, every camera moved: S and
//                        all terms, as the simulator records each step
// on dynamic9 (published: 6 targets, 5 cameras) and the generated scenes/large/crowd_100x30
// (100 targets, 30 cameras) and football_like (22 targets, 8 cameras). The moved camera's
// poses are drawn once, valid and near the targets, and taken in turn, so no call is answered
// from a kept sweep. Pin it to one core: taskset -c 0 build/tests/bench/bench_reward
#include <benchmark/benchmark.h>

#include <numbers>
#include <string>
#include <vector>

#include "kinematics/kinematics.h"
#include "reward/reward_model.h"
#include "scene/scene_loader.h"
#include "support/bench_scenes_dir.h"
#include "support/splitmix64.h"

namespace camcov {
namespace {

constexpr std::size_t kPoses = 64;  // distinct poses of the moved camera, taken in turn

struct Setup {
  scene::Scene scene;
  kinematics::World world;
  std::vector<geometry::Pose> team;   // the scene's cameras at t = 0
  std::vector<geometry::Pose> poses;  // for the moved camera
};

Setup setup(const std::string& file) {
  Setup s;
  s.scene = scene::loadScene(file);
  s.world = kinematics::Kinematics(s.scene).worldAt(0.0);
  for (const auto& c : s.scene.cameras)
    s.team.push_back(c.initial);
  // Poses 2–10 m from a target's first vertex, facing it: what the samplers draw.
  testing::SplitMix64 random{7};
  const geometry::Box box = geometry::boundingBox(s.world.boundary);
  while (s.poses.size() < kPoses) {
    const auto& target = s.world.targets[static_cast<std::size_t>(
        random.uniform(0.0, static_cast<double>(s.world.targets.size())))];
    const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
    const geometry::Vec2 p = target[0] + random.uniform(2.0, 10.0) * geometry::unitVector(angle);
    if (!geometry::contains(box, p)) continue;
    s.poses.push_back({p.x, p.y, angle + std::numbers::pi + random.uniform(-0.3, 0.3)});
  }
  return s;
}

std::string scenePath(const std::string& name) {
  if (name == "dynamic9") return (testing::benchScenesDir() / "dynamic9.json").string();
  return std::string(CAMCOV_LARGE_SCENES_DIR) + "/" + name + ".json";
}

}  // namespace

void Sweep(benchmark::State& state, const std::string& name) {
  const Setup s = setup(scenePath(name));
  visibility::Occluders occluders(s.world);
  visibility::Sweep sweep;
  const double theta = s.scene.cameras[0].lens.halfFov;
  std::size_t i = 0, seen = 0;
  for (auto _ : state) {
    seen += sweep.seenBy(occluders, 0, s.poses[i++ % kPoses], theta).size();
  }
  state.counters["intervals"] = static_cast<double>(seen) / static_cast<double>(i);
}

void Probe(benchmark::State& state, const std::string& name) {
  const Setup s = setup(scenePath(name));
  reward::RewardModel model(params::RewardParams{}, scene::lenses(s.scene));
  model.setWorld(s.world);
  std::vector<geometry::Pose> team = s.team;
  const std::size_t moved = team.size() / 2;
  std::size_t i = 0;
  for (auto _ : state) {
    team[moved] = s.poses[i++ % kPoses];
    benchmark::DoNotOptimize(model.reward(team));
  }
  state.counters["cameras"] = static_cast<double>(team.size());
}

void Evaluate(benchmark::State& state, const std::string& name) {
  const Setup s = setup(scenePath(name));
  reward::RewardModel model(params::RewardParams{}, scene::lenses(s.scene));
  model.setWorld(s.world);
  std::vector<geometry::Pose> team = s.team;
  std::size_t i = 0;
  for (auto _ : state) {
    for (auto& camera : team)
      camera = s.poses[i++ % kPoses];
    benchmark::DoNotOptimize(model.evaluate(team).reward);
  }
  state.counters["cameras"] = static_cast<double>(team.size());
}

}  // namespace camcov

int main(int argc, char** argv) {
  for (const std::string scene : {"dynamic9", "football_like", "crowd_100x30"}) {
    benchmark::RegisterBenchmark(("Sweep/" + scene).c_str(), camcov::Sweep, scene);
    benchmark::RegisterBenchmark(("Probe/" + scene).c_str(), camcov::Probe, scene);
    benchmark::RegisterBenchmark(("Evaluate/" + scene).c_str(), camcov::Evaluate, scene);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
