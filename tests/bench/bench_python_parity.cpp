// The C++ side of the visibility that the Python bindings are held to
// (tests/bench/python_parity.py runs this program and times the same work from Python):
//   Visibility/Segments    S and visibleBy for 1,000 random single-camera poses on dynamic9
//                          at t = 0, one query each, all of them collected (what
//                          Visibility.segments_each returns)
//   Visibility/Terms       the reward's terms for the same poses
// The poses come from splitmix64 with seed 1, uniform over the boundary's bounding box and
// the yaw circle: python_parity.py draws the very same ones.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <numbers>
#include <vector>

#include "kinematics/kinematics.h"
#include "reward/reward_model.h"
#include "scene/scene_loader.h"
#include "support/bench_scenes_dir.h"
#include "support/splitmix64.h"

namespace camcov {
namespace {

const scene::Scene& dynamic9() {
  static const scene::Scene s = scene::loadScene(testing::benchScenesDir() / "dynamic9.json");
  return s;
}

std::vector<geometry::Pose> randomPoses(const kinematics::World& world, int count) {
  const geometry::Box box = geometry::boundingBox(world.boundary);
  testing::SplitMix64 random{1};
  std::vector<geometry::Pose> poses;
  for (int i = 0; i < count; ++i) {
    const double x = random.uniform(box.min.x, box.max.x);
    const double y = random.uniform(box.min.y, box.max.y);
    poses.push_back({x, y, random.uniform(-std::numbers::pi, std::numbers::pi)});
  }
  return poses;
}

template <bool kCopySegments>
void visibility(benchmark::State& state) {
  const kinematics::World world = kinematics::Kinematics(dynamic9()).worldAt(0.0);
  reward::RewardModel model(params::RewardParams{}, scene::lenses(dynamic9()));
  model.setWorld(world);
  const std::vector<geometry::Pose> poses = randomPoses(world, 1000);
  std::vector<visibility::Segment> all;
  for (auto _ : state) {
    all.clear();
    for (const geometry::Pose& pose : poses) {
      const reward::RewardTerms t = model.evaluate(std::span(&pose, 1));
      if constexpr (kCopySegments)
        all.insert(all.end(), model.segments().begin(), model.segments().end());
      benchmark::DoNotOptimize(t.reward);
    }
    benchmark::DoNotOptimize(all.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(poses.size()));
}

BENCHMARK(visibility<true>)->Name("Visibility/Segments")->Unit(benchmark::kMicrosecond);
BENCHMARK(visibility<false>)->Name("Visibility/Terms")->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace camcov

BENCHMARK_MAIN();
