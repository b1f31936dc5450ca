// camcov-dec (control/decentralized_controller.h): each camera decides from its own knowledge.
#include "control/decentralized_controller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "control/event_kind.h"
#include "control/methods.h"
#include "sim/simulator.h"
#include "support/small_worlds.h"
#include "support/test_paths.h"

namespace camcov::control {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Two rooms: a wall along x = 0 (gaps of 5 cm at the ends, too narrow for a camera or a line
// of sight that reaches anything) keeps camera 0 and target 0 in the west, camera 1 and
// target 1 in the east, along `eastPath`.
std::string twoRooms(const std::string& eastPath, int westYaw = -34) {
  return R"js({
  "boundary": "POLYGON((-10 -5,10 -5,10 5,-10 5))",
  "targets": [{"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": "POLYGON((-5 0))"},
              {"shape": "POLYGON((-0.5 -0.5,0.5 -0.5,0.5 0.5,-0.5 0.5))", "path": ")js" +
         eastPath + R"js("}],
  "obstacles": [{"shape": "POLYGON((-0.25 -4.95,0.25 -4.95,0.25 4.95,-0.25 4.95))", "path": "POLYGON((0 0))"}],
  "cameraFoV": 30,
  "cameras": [{"pos": "POINT(-8 2)", "angle": )js" +
         std::to_string(westYaw) + R"js(, "maxVelocity": 1, "maxAngularVelocity": 1},
              {"pos": "POINT(8 -2)", "angle": 146, "maxVelocity": 1, "maxAngularVelocity": 1}]})js";
}

params::Parameters limited(double range, double loss = 0.0) {
  params::Parameters p;
  p.sim.duration = 6.0;  // two global steps: at dt and at dt + T1
  p.global.K = 100;
  p.knowledge.limited = true;
  p.comms.range = range;
  p.comms.loss = loss;
  return p;
}

// The commands a controller gave, step by step, and the poses and events of the run.
class Recorded final : public Controller, public sim::Recorder {
 public:
  explicit Recorded(std::unique_ptr<Controller> inner) : inner_(std::move(inner)) {}
  void control(const Observation& o, std::span<scene::CameraCommand> out) override {
    inner_->control(o, out);
    commands.emplace_back(out.begin(), out.end());
  }
  std::optional<geometry::Pose> goal(std::size_t j) const override { return inner_->goal(j); }
  void takeEvents(std::vector<ControlEvent>& out) override { inner_->takeEvents(out); }
  void step(const sim::StepRecord& r) override {
    poses.emplace_back(r.cameras.begin(), r.cameras.end());
    for (const auto& e : r.events) {
      events.push_back(e.kind + " " + std::to_string(e.camera) + " " + e.detail);
      if (e.kind == eventName(EventKind::NonFiniteCommand)) ++nonFinite;
    }
  }
  // Camera j's commands over the run, as (vx, vy, γ̇) triples.
  std::vector<std::vector<double>> of(std::size_t j) const {
    std::vector<std::vector<double>> out;
    for (const auto& step : commands)
      out.push_back({step[j].velocity.x, step[j].velocity.y, step[j].angularVelocity});
    return out;
  }
  std::vector<std::vector<scene::CameraCommand>> commands;
  std::vector<std::vector<geometry::Pose>> poses;
  std::vector<std::string> events;
  int nonFinite = 0;

 private:
  std::unique_ptr<Controller> inner_;
};

struct Run {
  Recorded recorded;
  sim::RunSummary summary;
};

std::unique_ptr<Run> run(const scene::Scene& scene, const params::Parameters& p, std::uint64_t seed,
                         const char* method = "camcov-dec") {
  auto r = std::make_unique<Run>(Run{Recorded(requireMethod(method).make(scene, p, seed)), {}});
  r->summary = sim::simulate(scene, p, r->recorded, r->recorded, seed);
  return r;
}

TEST(DecentralizedController, IsInTheTableRunOnlyWhenAskedFor) {
  const Method& method = requireMethod("camcov-dec");
  EXPECT_EQ(method.role, Role::example);
  const auto defaults = defaultMethods();
  EXPECT_EQ(std::count(defaults.begin(), defaults.end(), "camcov-dec"), 0);
}

TEST(DecentralizedController, TheSameSeedGivesTheSameRun) {
  const scene::Scene scene = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))"));
  const params::Parameters p = limited(10.0, 0.5);
  const auto a = run(scene, p, 7), b = run(scene, p, 7);
  EXPECT_EQ(a->recorded.poses, b->recorded.poses);
  EXPECT_EQ(a->recorded.events, b->recorded.events);
  EXPECT_EQ(a->summary.averageCoverage, b->summary.averageCoverage);
}

TEST(DecentralizedController, WithFullKnowledgeEveryCameraTakesItsPartOfCamcovsPlan) {
  // Every camera knows what the centralized method knows and draws from the same seed, so
  // the team moves as camcov moves it, pose for pose.
  const scene::Scene scene = testing::sceneFromJson(testing::kOneTargetScene);
  params::Parameters p;
  p.sim.duration = 6.0;
  p.global.K = 100;
  const auto ours = run(scene, p, 3), centralized = run(scene, p, 3, "camcov");
  EXPECT_EQ(ours->recorded.poses, centralized->recorded.poses);
  EXPECT_EQ(ours->summary.averageCoverage, centralized->summary.averageCoverage);
}

TEST(DecentralizedController, ACameraIgnoresWhatItNeitherSawNorHeard) {
  // Target 1 moves along one path or another in the east room. Camera 0, in the west, never
  // sees it; without messages it never hears of it either, so its commands are the same
  // bits whichever path target 1 takes, although camera 1's are not.
  const scene::Scene along = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))"));
  const scene::Scene across = testing::sceneFromJson(twoRooms("POLYGON((3 0,7 1,6 -3))"));
  const auto a = run(along, limited(0.0), 1), b = run(across, limited(0.0), 1);
  EXPECT_EQ(a->recorded.of(0), b->recorded.of(0));
  EXPECT_NE(a->recorded.of(1), b->recorded.of(1));
  // With messages camera 0 hears where target 1 is, and does differ (the check can fail).
  const auto heardA = run(along, limited(kInf), 1), heardB = run(across, limited(kInf), 1);
  EXPECT_NE(heardA->recorded.of(0), heardB->recorded.of(0));
}

TEST(DecentralizedController, ACameraThatKnowsNoTargetLooksRoundForOne) {
  // Camera 0 starts facing the north wall and hears nothing: it turns at its full rate until
  // target 0 comes into view, then plans for it and comes to cover it.
  const scene::Scene scene = testing::sceneFromJson(twoRooms("POLYGON((5 -2,5 2))", 90));
  const auto r = run(scene, limited(0.0), 1);
  const auto commands = r->recorded.of(0);
  EXPECT_EQ(commands.front(), (std::vector<double>{0.0, 0.0, 1.0}));
  const auto turning = std::count(commands.begin(), commands.end(), commands.front());
  EXPECT_GT(turning, 1);
  EXPECT_LT(turning, static_cast<long>(commands.size()));
  EXPECT_GT(r->summary.finalCoverage, 0.0);
}

// The published scenes with messages that reach everyone (`range` inf), or few of them.
void runEveryPublishedScene(const params::Parameters& p) {
  CAMCOV_REQUIRE_PUBLISHED_SCENES();
  const auto files = testing::jsonFilesIn(testing::publishedScenesDir());
  EXPECT_EQ(files.size(), 32U);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    const scene::Scene scene = scene::loadScene(file);
    const auto r = run(scene, p, 1);
    EXPECT_EQ(r->summary.steps, static_cast<int>(std::llround(p.sim.duration / p.sim.dt)) + 1);
    EXPECT_EQ(r->recorded.nonFinite, 0);
    // The safety layer still stands between the commands and the cameras.
    EXPECT_EQ(r->summary.avoidableContacts, 0);
    EXPECT_GE(r->summary.averageCoverage, 0.0);
    EXPECT_LE(r->summary.averageCoverage, 1.0);
  }
}

TEST(DecentralizedController, RunsEveryPublishedSceneWithMessagesThatReachEveryone) {
  params::Parameters p = limited(kInf);
  p.global.K = 500;
  p.sim.duration = 10.0;
  runEveryPublishedScene(p);
}

TEST(DecentralizedController, RunsEveryPublishedSceneWhenHalfTheMessagesAreLost) {
  params::Parameters p = limited(10.0, 0.5);
  p.global.K = 500;
  p.sim.duration = 10.0;
  p.comms.latency = 0.2;
  runEveryPublishedScene(p);
}

}  // namespace
}  // namespace camcov::control
