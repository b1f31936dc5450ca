#include "sim/simulator.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "control/event_kind.h"
#include "support/small_worlds.h"

namespace camcov::sim {
namespace {

// Asks every camera for the same command, and remembers what it was shown.
class ConstantController final : public control::Controller {
 public:
  explicit ConstantController(scene::CameraCommand u) : u_(u) {}
  void control(const control::Observation& o, std::span<scene::CameraCommand> out) override {
    seenTimes.push_back(o.time);
    seenWorldTimes.push_back(o.world.time);
    for (auto& c : out)
      c = u_;
    events_.push_back({o.time, "tick", -1, "", {}, {}});
  }
  std::optional<geometry::Pose> goal(std::size_t) const override { return geometry::Pose{1, 2, 3}; }
  void takeEvents(std::vector<control::ControlEvent>& out) override {
    out.insert(out.end(), events_.begin(), events_.end());
    events_.clear();
  }
  std::vector<double> seenTimes, seenWorldTimes;

 private:
  scene::CameraCommand u_;
  std::vector<control::ControlEvent> events_;
};

class KeepingRecorder final : public Recorder {
 public:
  void step(const StepRecord& r) override {
    times.push_back(r.time);
    poses.emplace_back(r.cameras.begin(), r.cameras.end());
    coverage.push_back(r.terms.coverage);
    events += static_cast<int>(r.events.size());
    ASSERT_TRUE(r.goals[0].has_value());
  }
  std::vector<double> times, coverage;
  std::vector<std::vector<geometry::Pose>> poses;
  int events = 0;
};

const scene::Scene& oneTargetScene() {
  static const scene::Scene s = testing::sceneFromJson(testing::kOneTargetScene);
  return s;
}

TEST(Simulate, StepsAtFixedDtAndShowsTheControllerOnlyThePresent) {
  params::Parameters p;
  p.sim.duration = 2.0;
  ConstantController controller({{0, 0}, 0});
  KeepingRecorder recorder;
  const RunSummary s = simulate(oneTargetScene(), p, controller, recorder);
  EXPECT_EQ(s.steps, 21);
  ASSERT_EQ(recorder.times.size(), 21u);
  EXPECT_DOUBLE_EQ(recorder.times.back(), 2.0);
  ASSERT_EQ(controller.seenTimes.size(), 20u) << "no command is needed after the last step";
  for (std::size_t k = 0; k < controller.seenTimes.size(); ++k) {
    EXPECT_DOUBLE_EQ(controller.seenTimes[k], recorder.times[k]);
    EXPECT_DOUBLE_EQ(controller.seenWorldTimes[k], recorder.times[k]);
  }
  EXPECT_EQ(recorder.events, 20);
}

// Camera 0 asks for NaN on steps 3 to 5 and for an infinite turn on step 8; camera 1 always
// for a finite move.
class BuggyController final : public control::Controller {
 public:
  void control(const control::Observation& o, std::span<scene::CameraCommand> out) override {
    const auto k = static_cast<int>(std::lround(o.time / 0.1));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out[0] = (k >= 3 && k <= 5) ? scene::CameraCommand{{nan, 0.0}, 0.0}
             : k == 8           ? scene::CameraCommand{{0.0, 0.0}, HUGE_VAL}
                                : scene::CameraCommand{{1.0, 0.0}, 0.0};
    for (std::size_t j = 1; j < out.size(); ++j)
      out[j] = {{1.0, 0.0}, 0.0};
  }
  std::optional<geometry::Pose> goal(std::size_t) const override { return geometry::Pose{}; }
  void takeEvents(std::vector<control::ControlEvent>&) override {}
};

class EventRecorder final : public Recorder {
 public:
  void step(const StepRecord& r) override {
    events.insert(events.end(), r.events.begin(), r.events.end());
    poses.emplace_back(r.cameras.begin(), r.cameras.end());
  }
  std::vector<control::ControlEvent> events;
  std::vector<std::vector<geometry::Pose>> poses;
};

TEST(Simulate, ANonFiniteCommandHoldsTheCameraAndIsAnEventAtTheStartOfEachStretch) {
  params::Parameters p;
  p.sim.duration = 1.0;
  BuggyController controller;
  EventRecorder recorder;
  simulate(oneTargetScene(), p, controller, recorder);
  std::vector<control::ControlEvent> found;
  for (const auto& e : recorder.events)
    if (e.kind == control::eventName(control::EventKind::NonFiniteCommand)) found.push_back(e);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0].time, 0.3, 1e-12);
  EXPECT_NEAR(found[1].time, 0.8, 1e-12);
  EXPECT_EQ(found[0].camera, 0);
  EXPECT_NE(found[0].detail.find("vx nan"), std::string::npos) << found[0].detail;
  EXPECT_NE(found[1].detail.find("yaw rate inf"), std::string::npos) << found[1].detail;
  // Steps 3 to 5 do not move camera 0 (the poses recorded at 0.3 s to 0.6 s are one), while
  // its finite steps move it 0.1 m each.
  for (int k = 3; k <= 5; ++k)
    EXPECT_EQ(recorder.poses[k + 1][0].x, recorder.poses[k][0].x) << k;
  EXPECT_NEAR(recorder.poses[3][0].x - recorder.poses[2][0].x, 0.1, 1e-12);
}

TEST(Simulate, SaturatesCommandsToTheCameraLimits) {
  params::Parameters p;
  p.sim.duration = 1.0;
  ConstantController controller({{30, 40}, -9});  // 50 m/s, -9 rad/s
  KeepingRecorder recorder;
  simulate(oneTargetScene(), p, controller, recorder);
  // Camera 0 starts at (-6, -6) with v_max 2 m/s and 1 rad/s: 1 s later it is 2 m along
  // (0.6, 0.8) and has turned -1 rad.
  const geometry::Pose end = recorder.poses.back()[0];
  EXPECT_NEAR(end.x, -6 + 1.2, 1e-9);
  EXPECT_NEAR(end.y, -6 + 1.6, 1e-9);
  EXPECT_NEAR(geometry::wrapAngle(end.yaw - geometry::degToRad(225)), -1.0, 1e-9);
}

// Every camera commanded at 2 m/s in +x for 10 s: camera 1, at x = 6, meets the wall x = 10
// after 2 s.
struct WallRun {
  double largestX = -std::numeric_limits<double>::infinity();  // of any camera, ever
  double lastX = 0.0;                                          // of camera 1 at the end
  RunSummary summary;
};

WallRun driveIntoTheWall(bool safetyLayer) {
  params::Parameters p;
  p.safety.enabled = safetyLayer;
  p.sim.duration = 10.0;
  ConstantController controller({{2, 0}, 0});
  KeepingRecorder recorder;
  WallRun r;
  r.summary = simulate(oneTargetScene(), p, controller, recorder);
  for (const auto& step : recorder.poses) {
    for (const auto& c : step)
      r.largestX = std::max(r.largestX, c.x);
  }
  r.lastX = recorder.poses.back()[1].x;
  return r;
}

TEST(Simulate, KeepsCamerasInsideTheBoundaryWithoutTheSafetyLayer) {
  // The simulator's own clamp, the last line of defence: up to the wall, not through it.
  const WallRun r = driveIntoTheWall(false);
  EXPECT_LE(r.largestX, 10.0);
  EXPECT_GT(r.lastX, 9.99);
  EXPECT_GT(r.summary.boundaryClamps, 0);
}

TEST(Simulate, TheSafetyLayerStopsCamerasJustInsideTheBoundary) {
  const WallRun r = driveIntoTheWall(true);
  EXPECT_LT(r.largestX, 10.0);
  EXPECT_GT(r.lastX, 9.99);  // 1 mm clear of the wall, not held back
  EXPECT_EQ(r.summary.boundaryClamps, 0) << "the layer, not the clamp, keeps it inside";
}

TEST(Simulate, AveragesAreTheTrapezoidRuleOfTheRecordedSeries) {
  params::Parameters p;
  p.sim.duration = 3.0;
  ConstantController controller({{1, 1}, 0.3});
  KeepingRecorder recorder;
  const RunSummary s = simulate(oneTargetScene(), p, controller, recorder);
  double integral = 0;
  for (std::size_t k = 1; k < recorder.coverage.size(); ++k) {
    integral += 0.5 * (recorder.coverage[k - 1] + recorder.coverage[k]) * p.sim.dt;
  }
  EXPECT_NEAR(s.averageCoverage, integral / 3.0, 1e-12);
}

TEST(Simulate, RecordsResolutionCoverageForASceneThatAsksForIt) {
  // A camera 5 m below the 2 m square's bottom edge, facing it: it sees that edge alone (0.25
  // of the perimeter). k = W / 2θ; at x along the edge ρ = 5k / (25 + x²), and with ρ_min =
  // 5k / 25.5 the edge is resolved where x² ≤ 0.5: 2√0.5 m of the 8 m perimeter.
  const double k = 1000.0 / (std::numbers::pi / 3);
  const scene::Scene scene = testing::sceneFromJson(fmt::format(R"js({{
    "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
    "targets": [{{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))"}}],
    "cameraFoV": 30, "imageWidth": 1000, "resolution": {{"minDensity": {}}},
    "cameras": [{{"pos": "POINT(0 -6)", "angle": 90, "maxVelocity": 2,
                  "maxAngularVelocity": 1}}]}})js",
                                                                5.0 * k / 25.5));
  params::Parameters p;
  p.sim.duration = 1.0;
  ConstantController still({{0, 0}, 0});
  KeepingRecorder recorder;
  const RunSummary s = simulate(scene, p, still, recorder);
  EXPECT_NEAR(s.averageCoverage, 0.25, 1e-12);
  ASSERT_TRUE(s.averageResolutionCoverage.has_value());
  EXPECT_NEAR(*s.averageResolutionCoverage, 2.0 * std::sqrt(0.5) / 8.0, 1e-12);
  EXPECT_NEAR(*s.finalResolutionCoverage, 2.0 * std::sqrt(0.5) / 8.0, 1e-12);
  // A scene without one records none.
  const RunSummary plain = simulate(oneTargetScene(), p, still, recorder);
  EXPECT_FALSE(plain.averageResolutionCoverage.has_value());
}

TEST(Simulate, MeasuresCollisionTimeBelowDelta) {
  // A camera parked 0.3 m from the obstacle (δ = 0.5 m) for the whole run.
  const scene::Scene s = testing::sceneFromJson(R"js({
    "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
    "targets": [{"shape": "POLYGON((-1 -1,1 -1,1 1,-1 1))", "path": "POLYGON((0 0))"}],
    "obstacles": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((5 0))"}],
    "cameraFoV": 30,
    "cameras": [{"pos": "POINT(5 -0.8)", "angle": 0, "maxVelocity": 2, "maxAngularVelocity": 1}]})js");
  params::Parameters p;
  p.safety.enabled = false;  // the layer would move it away
  p.sim.duration = 1.5;
  ConstantController controller({{0, 0}, 0});
  KeepingRecorder recorder;
  const RunSummary summary = simulate(s, p, controller, recorder);
  EXPECT_NEAR(summary.minObjectDistance, 0.3, 1e-12);
  EXPECT_NEAR(summary.objectCollisionTime, 1.5, 1e-9);
  EXPECT_TRUE(std::isinf(summary.minCameraDistance));
  EXPECT_EQ(summary.cameraCollisionTime, 0.0);
}

// Records every field of every step, to compare two runs byte for byte.
class FingerprintRecorder final : public Recorder {
 public:
  void step(const StepRecord& r) override {
    char line[256];
    std::snprintf(line, sizeof line, "%d %a %a %a %a %zu", r.index, r.time, r.terms.coverage,
                  r.terms.reward, r.minObjectDistanceInStep, r.events.size());
    text += line;
    for (const auto& c : r.cameras) {
      std::snprintf(line, sizeof line, " %a,%a,%a", c.x, c.y, c.yaw);
      text += line;
    }
    text += "\n";
  }
  std::string text;
};

TEST(Simulation, SteppedByHandIsTheSameRunAsSimulate) {
  params::Parameters p;
  p.sim.duration = 1.5;
  const scene::CameraCommand u{{0.7, -0.4}, 0.3};
  ConstantController a(u), b(u);
  FingerprintRecorder whole, stepped;
  const RunSummary expected = simulate(oneTargetScene(), p, a, whole);

  Simulation simulation(oneTargetScene(), p);
  std::vector<scene::CameraCommand> commands(2);
  std::vector<std::optional<geometry::Pose>> goals(2, geometry::Pose{1, 2, 3});
  int instants = 0;
  while (!simulation.finished()) {
    EXPECT_DOUBLE_EQ(simulation.observation().time, instants * p.sim.dt);
    if (!simulation.atLastInstant()) {
      b.control(simulation.observation(), commands);
      simulation.command(commands);
    }
    b.takeEvents(simulation.events());
    simulation.advance(goals, stepped);
    ++instants;
  }
  EXPECT_EQ(instants, 16);
  EXPECT_EQ(stepped.text, whole.text);
  const RunSummary got = simulation.summary();
  EXPECT_EQ(got.steps, expected.steps);
  EXPECT_EQ(got.averageCoverage, expected.averageCoverage);
  EXPECT_EQ(got.averageReward, expected.averageReward);
  EXPECT_EQ(got.finalCoverage, expected.finalCoverage);
  EXPECT_EQ(got.minObjectDistance, expected.minObjectDistance);
}

TEST(Simulation, ACallerCommandsEachStepAndWithoutCommandsTheCamerasHoldStill) {
  params::Parameters p;
  p.sim.duration = 0.3;
  p.safety.enabled = false;
  Simulation simulation(oneTargetScene(), p);
  FingerprintRecorder recorder;
  const geometry::Pose start = simulation.cameras()[1];
  // Camera 1 (2 m/s, 1 rad/s) asked for 5 m/s along x and 0.5 rad/s: saturated to 2 m/s.
  const std::vector<scene::CameraCommand> fast{{{0, 0}, 0}, {{5, 0}, 0.5}};
  simulation.command(fast);
  simulation.advance({}, recorder);
  EXPECT_NEAR(simulation.cameras()[1].x - start.x, 2.0 * p.sim.dt, 1e-12);
  EXPECT_NEAR(simulation.cameras()[1].yaw - start.yaw, 0.5 * p.sim.dt, 1e-12);
  // No command this step: the camera stays where it is.
  const geometry::Pose after = simulation.cameras()[1];
  simulation.advance({}, recorder);
  EXPECT_EQ(simulation.cameras()[1], after);
  simulation.command(fast);
  simulation.advance({}, recorder);
  EXPECT_TRUE(simulation.atLastInstant());
  EXPECT_THROW(simulation.command(fast), std::logic_error);
  simulation.advance({}, recorder);
  EXPECT_TRUE(simulation.finished());
  EXPECT_THROW(simulation.advance({}, recorder), std::logic_error);
  EXPECT_EQ(simulation.summary().steps, 4);
  EXPECT_EQ(std::count(recorder.text.begin(), recorder.text.end(), '\n'), 4);
}

}  // namespace
}  // namespace camcov::sim
