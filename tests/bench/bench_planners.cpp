// What a roadmap of section V-C costs, as the paper's method builds one at every planning event:
//   Roadmap/<scene>   the PRM* roadmap of the scene's world at t = 0 (T2's budget of milestones,
//                     default parameters), for its first camera's lens; a new seed each time
//   Query/<scene>     that roadmap's queries between the scene's cameras and poses it drew
// The neighbour search, the motion checks and eq. (10)'s costs are most of the first; the
// searches of the second. Pin it to one core:
//   COVERAGE_SCENES_DIR=../shared/coverage_scenes taskset -c 0 build/tests/bench/bench_planners
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "kinematics/kinematics.h"
#include "planners/motion_planner.h"
#include "scene/scene_loader.h"
#include "support/bench_scenes_dir.h"

namespace camcov::planners {
namespace {

struct Setup {
  scene::Scene scene;
  kinematics::World world;
  params::Parameters params;
};

Setup setup(const std::string& name) {
  Setup s;
  s.scene = scene::loadScene((testing::benchScenesDir() / (name + ".json")).string());
  s.world = kinematics::Kinematics(s.scene).worldAt(0.0);
  return s;
}

void BuildRoadmap(benchmark::State& state, const std::string& name) {
  const Setup s = setup(name);
  std::uint64_t seed = 1;
  std::size_t milestones = 0, built = 0;
  for (auto _ : state) {
    const Roadmap roadmap(s.world, s.params, s.scene.cameras[0].lens, seed++);
    milestones += roadmap.milestones();
    ++built;
  }
  state.counters["milestones"] = static_cast<double>(milestones) / static_cast<double>(built);
}

void Query(benchmark::State& state, const std::string& name) {
  const Setup s = setup(name);
  Roadmap roadmap(s.world, s.params, s.scene.cameras[0].lens, 1);
  // From every camera to every other camera's pose, turned half a circle: paths that cross the
  // room, each end joining the roadmap as the controller's queries do.
  std::vector<std::pair<geometry::Pose, geometry::Pose>> trips;
  for (const auto& from : s.scene.cameras) {
    for (const auto& to : s.scene.cameras) {
      geometry::Pose goal = to.initial;
      goal.yaw = geometry::wrapAngle(goal.yaw + 3.14159);
      trips.emplace_back(from.initial, goal);
    }
  }
  std::size_t i = 0, found = 0;
  for (auto _ : state) {
    const auto& [start, goal] = trips[i++ % trips.size()];
    found += roadmap.query(start, goal).has_value() ? 1 : 0;
  }
  state.counters["found"] = static_cast<double>(found) / static_cast<double>(i);
}

}  // namespace

BENCHMARK_CAPTURE(BuildRoadmap, dynamic9, std::string("dynamic9"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BuildRoadmap, static1, std::string("static1"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BuildRoadmap, dynamic16, std::string("dynamic16"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(Query, dynamic9, std::string("dynamic9"))->Unit(benchmark::kMicrosecond);

}  // namespace camcov::planners

BENCHMARK_MAIN();
